#version 300 es
precision highp float;
// A call of a function without a body, even from a function nobody calls.
out vec4 o;
float u(float x);
float f() { return u(1.0); }
void main() { o = vec4(1.0); }
