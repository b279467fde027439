precision mediump float;
// A plain fragment shader: the vertex shader's uniforms alone are too many.
void main() { gl_FragColor = vec4(1.0); }
