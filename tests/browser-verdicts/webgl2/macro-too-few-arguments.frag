#version 300 es
precision highp float;
// Two parameters, one (empty) argument: browsers reject it too.
out vec4 o;
#define F(a, b) a vec4(1.0)
void main() { o = F(); }
