precision mediump float;
// Still GLSL ES 1.00, but the vertex shader is #version 300 es: the versions differ.
varying vec2 vUv;
void main() { gl_FragColor = vec4(vUv, 0.0, 1.0); }
