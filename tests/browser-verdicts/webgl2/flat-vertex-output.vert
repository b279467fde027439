#version 300 es
in vec4 p;
flat out int id;
void main() { gl_Position = p; id = 1; }
