#version 300 es
precision highp float;
out vec4 o;
void main() { switch (1u) { case 1: break; } o = vec4(1.0); }
