#version 300 es
precision highp float;
out vec4 o;
#define AA 1
#if AA > 1
float f = 08;
#else
float f = 1.0;
#endif
void main() { o = vec4(f); }
