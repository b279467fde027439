precision mediump float;
// 20000 floats take 80,000 bytes: more than browsers allow for a private variable.
float history[20000];
void main() {
  history[0] = 1.0;
  gl_FragColor = vec4(history[0]);
}
