precision mediump float;
// Two declarations on one line: glslang puts its error for the second at the first.
void main() {
  float x = gl_FragCoord.x; const float c = (1.0, 2.0);
  gl_FragColor = vec4(x * c);
}
