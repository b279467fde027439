#version 300 es
precision highp float;
#define EPS.001
#define N 4u
#if N == 4u
#define K 2.0
#endif
out vec4 o;
void main() { o = vec4(EPS * K); }
