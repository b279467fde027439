precision mediump float;
// A late 'disable' is an error even in WebGL 1.
#extension GL_OES_standard_derivatives : disable
void main() { gl_FragColor = vec4(1.0); }
