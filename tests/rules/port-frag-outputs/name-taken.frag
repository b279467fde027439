precision mediump float;
uniform vec4 fragColor;
void main() {
  gl_FragColor = fragColor;
}
