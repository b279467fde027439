#version 300 es
precision highp float;
#define PERF 1e
#define BIG 4294967296
#define OCT(x) (x + 08)
out vec4 o;
void main() { o = vec4(1.0); }
