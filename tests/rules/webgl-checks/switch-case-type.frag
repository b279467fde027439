#version 300 es
precision highp float;
out vec4 c;
void main() { uint k = 1u; switch (k) { case 1: c = vec4(1.0); break; default: c = vec4(0.0); } }
