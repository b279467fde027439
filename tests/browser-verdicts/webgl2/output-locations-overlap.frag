#version 300 es
precision highp float;
layout(location = 0) out vec4 a[2];
layout(location = 1) out vec4 b;
void main() { a[0] = vec4(1.0); b = a[0]; }
