#version 300 es
// A vertex input at location 16: WebGL 2 has attribute locations 0 to 15 only.
layout(location = 16) in vec4 position;
void main() { gl_Position = position; }
