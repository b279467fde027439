#version 300 es
precision highp float;
out vec4 o;
struct d1 { float a; };
void main(){ vec2 a, d1; d1 = vec2(1.0); a = d1; o = vec4(a, d1); }