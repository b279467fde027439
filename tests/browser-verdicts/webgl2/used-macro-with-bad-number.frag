#version 300 es
precision highp float;
#define PERF 1e
out vec4 o;
void main() { o = vec4(PERF); }
