#version 300 es
precision highp float;
out vec4 o;
void main() { flat float x = 1.0; o = vec4(x); }
