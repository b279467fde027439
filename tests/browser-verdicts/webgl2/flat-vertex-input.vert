#version 300 es
flat in vec4 p;
void main() { gl_Position = p; }
