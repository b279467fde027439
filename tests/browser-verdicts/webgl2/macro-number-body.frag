#version 300 es
precision highp float;
// No space between an object-like macro's name and a body starting with '.'.
out vec4 o;
#define SURFACE_DIST.001
void main() { o = vec4(SURFACE_DIST); }
