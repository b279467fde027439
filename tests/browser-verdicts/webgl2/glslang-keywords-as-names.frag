#version 300 es
precision highp float;
out vec4 o;
void main() { float shared = 1.0; float dmat2 = shared; o = vec4(dmat2); }
