#extension GL_OES_standard_derivatives : enable
// The page enables what the shader asks for.
precision mediump float;
void main() { gl_FragColor = vec4(dFdx(1.0)); }
