#version 300 es
precision highp float;
#define W(a) 2.0 * cos(a + 1.0)

// W() inside another macro: one empty argument in browsers.
#define P (W(1.0) - W())
out vec4 c;
void main() { c = vec4(P); }
