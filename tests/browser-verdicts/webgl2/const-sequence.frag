#version 300 es
precision highp float;
// The sequence operator is no constant expression in GLSL ES 3.00.
out vec4 o;
const float c = (1.0, 2.0);
void main() { o = vec4(c); }
