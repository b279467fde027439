// GLSL ES 1.00 in WebGL 1: only a warning.
precision mediump float;
#extension GL_OES_standard_derivatives : enable
void main() { gl_FragColor = vec4(1.0); }
