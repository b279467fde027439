#version 300 es
precision highp float;
// Two outputs: both need a location.
out vec4 a;
out vec4 b;
void main() { a = vec4(1.0); b = a; }
