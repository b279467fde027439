precision mediump float;
uniform float level;
void main() {
  float length = 2.0 * level;
  gl_FragColor = vec4(length);
}
