#version 300 es
// Two layout qualifiers on one block: GLSL ES 3.00 allows one layout(...) per declaration.
layout(std140) layout(row_major) uniform Transform { mat4 model; };
in vec4 position;
void main() { gl_Position = model * position; }
