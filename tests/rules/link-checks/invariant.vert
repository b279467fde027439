// vUv is invariant here; the fragment shader's vUv is not.
attribute vec4 position;
invariant varying vec2 vUv;
void main() { vUv = position.xy; gl_Position = position; }
