#version 300 es
precision highp float;
// A trailing comma in a macro's parameter list: browsers accept it.
out vec4 o;
#define lerp(a, b, k,) mix(a, b, k)
void main() { o = vec4(lerp(0.0, 1.0, 0.5)); }
