#version 300 es
precision mediump float;
// flat on a uniform: interpolation qualifiers belong to values passed between the stages.
flat uniform int mode;
out vec4 color;
void main() { color = vec4(float(mode)); }
