#version 300 es
precision highp float;
layout(packed) uniform B { vec4 v; };
out vec4 c;
void main() { c = v; }
