#version 300 es
precision highp float;
out vec4 o;
float mix(float a, float b, float c) { return a; }
void main() { o = vec4(mix(1.0, 2.0, 0.5)); }
