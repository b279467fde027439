precision mediump float;
// Reads vColor as a vec4, but the vertex shader writes a vec3: the types differ.
varying vec4 vColor;
void main() { gl_FragColor = vColor; }
