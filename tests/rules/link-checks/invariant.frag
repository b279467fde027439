precision mediump float;
// vUv without invariant, but the vertex shader's is invariant: GLSL ES 1.00 needs both or neither.
varying vec2 vUv;
void main() { gl_FragColor = vec4(vUv, 0.0, 1.0); }
