#version 300 es
// Only the first location is checked: a mat4 at 13 compiles.
layout(location = 13) in mat4 m;
layout(location = 1) in vec4 a;
layout(location = 1) in vec4 b;
void main() { gl_Position = m[0] + a + b; }
