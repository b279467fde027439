#version 300 es
precision highp float;
// An #extension line after a declaration: an error in GLSL ES 3.00.
out vec4 o;
#extension GL_OES_standard_derivatives : enable
void main() { o = vec4(1.0); }
