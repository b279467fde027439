precision mediump float;

// Paints everything white.
void main() {
  gl_FragColor = vec4(1.0);
  gl_FragColor.a = 0.5;
}
