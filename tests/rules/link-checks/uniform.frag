precision mediump float;
// The same uTime, mediump here under the default precision: the precisions differ.
uniform float uTime;
void main() { gl_FragColor = vec4(fract(uTime)); }
