#version 300 es
precision highp float;
// ANGLE does not reserve 'texture' (an overload needs an extension): a shader may declare it.
out vec4 o;
float texture(vec2 x) { return x.x; }
void main() { o = vec4(texture(vec2(1.0))); }
