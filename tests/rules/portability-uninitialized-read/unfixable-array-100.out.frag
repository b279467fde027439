precision mediump float;
void main() {
  float w[2];
  gl_FragColor = vec4(w[1]);
}
