precision mediump float;
// Both the declaration and the use of `round` come from one macro body.
#define ROUNDED(v) float round = floor(v + 0.5); float y = round;
float f(float x) {
  ROUNDED(x)
  return y;
}
void main() {
  gl_FragColor = vec4(f(0.3));
}
