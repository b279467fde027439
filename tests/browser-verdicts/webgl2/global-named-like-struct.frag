#version 300 es
precision highp float;
out vec4 o;
struct d1 { float a; };
vec2 a, d1;
void main(){ d1 = vec2(1.0); o = vec4(a, d1); }