#extension GL_OES_standard_derivatives : enable
// WebGL 2 has no OES_standard_derivatives for GLSL ES 1.00 code: dFdx is missing.
precision mediump float;
void main() { gl_FragColor = vec4(dFdx(1.0)); }
