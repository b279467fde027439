// GLSL ES 1.00 in a WebGL 2 context: also an error there.
precision mediump float;
#extension GL_OES_standard_derivatives : enable
void main() { gl_FragColor = vec4(1.0); }
