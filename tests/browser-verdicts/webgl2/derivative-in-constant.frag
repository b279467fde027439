#version 300 es
precision mediump float;
out vec4 o;
const float d = dFdx(1.0);
void main() { o = vec4(d); }
