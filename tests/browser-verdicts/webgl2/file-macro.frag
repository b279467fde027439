#version 300 es
precision highp float;
out vec4 o;
void main() { int f = __FILE__; o = vec4(float(f)); }
