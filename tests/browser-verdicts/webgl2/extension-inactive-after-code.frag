#version 300 es
precision highp float;
// The same line in a skipped #if group: nothing to reject.
out vec4 o;
#if 0
#extension GL_OES_standard_derivatives : enable
#endif
void main() { o = vec4(1.0); }
