precision mediump float;
uniform float u;
void main() {
  float x;
  gl_FragColor = vec4(x * u);
}
