#version 300 es
precision highp float;
// 16,384 floats are 65,536 bytes: one byte too many for a private variable.
out vec4 o;
void main() { float a[16384]; a[0] = 1.0; o = vec4(a[0]); }
