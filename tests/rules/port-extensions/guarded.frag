#ifdef GL_OES_standard_derivatives
#extension GL_OES_standard_derivatives : enable
#endif
precision mediump float;
void main() {
  gl_FragColor = vec4(1.0);
}
