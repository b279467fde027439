#extension GL_EXT_made_up : enable
precision mediump float;
void main() {
  gl_FragColor = vec4(1.0);
}
