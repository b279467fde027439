#version 300 es
precision highp float;
// One output, an array: no location needed.
out vec4 a[2];
void main() { a[0] = vec4(1.0); a[1] = a[0]; }
