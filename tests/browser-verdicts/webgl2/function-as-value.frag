#version 300 es
precision highp float;
out vec4 o;
uniform int n;
void main() { float t = float(abs); o = vec4(t); }
