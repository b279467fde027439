#version 300 es
precision highp float;
out vec4 o;
// A global variable hides the built-in function of its name.
uniform int abs;
void main() { o = vec4(abs(-1.0)); }
