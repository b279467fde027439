#version 300 es
// The file ends with a backslash that no line end follows.
precision mediump float;
out vec4 color;
void main() { color = vec4(1.0); } \