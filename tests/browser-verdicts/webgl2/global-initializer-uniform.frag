#version 300 es
precision highp float;
// Non-constant global initialisers: an error in GLSL ES 3.00.
uniform float u;
float g = u;
out vec4 o;
void main() { o = vec4(g); }
