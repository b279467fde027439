precision mediump float;
uniform float u;
void main() {
  float x = 0.0;
  gl_FragColor = vec4(x * u);
}
