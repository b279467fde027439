#version 300 es
precision highp float;
out vec4 o;
#define RES (64u)
#if RES % 2u != 0u
#error odd
#endif
#ifdef LOW
#define SIZE 32u
#else
#define SIZE 64u
#endif
#if SIZE == 64u
void main() { o = vec4(float(RES + SIZE)); }
#endif
