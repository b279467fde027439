precision mediump float;
void main() {
  // floor without a call: a built-in function's name is not a value.
  float t = floor;
  gl_FragColor = vec4(t);
}
