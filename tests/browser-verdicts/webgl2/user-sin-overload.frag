#version 300 es
precision highp float;
// Other built-in names are reserved in GLSL ES 3.00, even for a new overload.
out vec4 o;
float sin(vec2 x, vec2 y) { return x.x; }
void main() { o = vec4(sin(vec2(1.0), vec2(2.0))); }
