#version 300 es
precision highp float;
out vec4 o;
void f(lowp float x);
void f(highp float x) {}
void main() { f(1.0); o = vec4(1.0); }
