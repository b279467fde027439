#version 300 es
precision highp float;
layout(location = 6) out vec4 a[3];
void main() { a[0] = vec4(1.0); }
