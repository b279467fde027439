#version 300 es
// A float literal as an array size: a constant expression, but not an integer one;
// browsers reject it as glslang does (it must not be lowered as "a constant glslang
// cannot fold").
precision highp float;
uniform vec3 r[3.5e38];
out vec4 c;
void main() { c = vec4(r[0], 1.0); }
