#version 300 es
precision highp float;
layout(location = 0) out vec4 a;
out vec4 b;
void main() { a = vec4(1.0); b = a; }
