#version 300 es
precision highp float;
// F() passes one empty argument to a one-parameter macro; glslang says 'Too few args'.
out vec4 o;
#define F(a) a vec4(1.0)
void main() { o = F(); }
