#version 300 es
precision highp float;
flat in float x;
out vec4 o;
void main() { o = vec4(x); }
