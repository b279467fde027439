#version 300 es
precision highp float;
out vec4 c;
void main() { const float d = dFdx(1.0); c = vec4(d); }
