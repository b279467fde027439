#version 300 es
layout(location = 0) layout(location = 1) in vec4 a;
void main() { gl_Position = a; }
