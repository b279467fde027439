#version 300 es
// Directives before the #extension line are fine.
#define ONE 1.0
#extension GL_EXT_sp_unknown : warn
precision highp float;
out vec4 o;
void main() { o = vec4(ONE); }
