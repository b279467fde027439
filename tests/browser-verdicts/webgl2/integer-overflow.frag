#version 300 es
precision highp float;
// ... and an error in GLSL ES 3.00.
out vec4 o;
void main() { int i = 4294967296; o = vec4(float(i)); }
