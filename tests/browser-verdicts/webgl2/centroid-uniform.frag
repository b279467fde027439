#version 300 es
precision highp float;
centroid uniform float u;
out vec4 o;
void main() { o = vec4(u); }
