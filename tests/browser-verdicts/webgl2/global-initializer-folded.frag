#version 300 es
precision highp float;
out vec4 o;
float T = 2. * asinh(1.);
float N = uintBitsToFloat(0x7f800001u);
mat3 m = mat3((1.0 / 16.0) * (1.0, 2.0, 1.0));
void main() { o = vec4(T, N, m[0].x, 1.0); }
