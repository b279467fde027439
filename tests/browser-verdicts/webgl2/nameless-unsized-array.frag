#version 300 es
precision mediump float;
// With no size, browsers reject it: "empty array declaration needs to specify a size".
float [];
out vec4 c;
void main() { c = vec4(1.0); }
