// uTime takes the vertex shader's default float precision, highp.
attribute vec4 position;
uniform float uTime;
void main() { gl_Position = position + vec4(sin(uTime)); }
