#version 300 es
precision highp float;
out vec4 o;
#ifdef HIRES
float f = 1e;
uint u = 08u;
#else
float f = 1e+2 * 2.5E-1;
#endif
void main() { o = vec4(f); }
