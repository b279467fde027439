#version 0300 es
// Browsers read the version as a C integer: 0300 is octal 192.
precision highp float;
out vec4 o;
void main() { o = vec4(1.0); }
