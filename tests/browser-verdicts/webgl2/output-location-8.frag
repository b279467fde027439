#version 300 es
precision highp float;
layout(location = 8) out vec4 a;
void main() { a = vec4(1.0); }
