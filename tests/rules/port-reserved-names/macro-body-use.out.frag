#version 300 es
precision mediump float;
// Both the declaration and the use of `round` come from one macro body.
#define ROUNDED(v) float round_ = floor(v + 0.5); float y = round_;
out highp vec4 fragColor;
float f(float x) {
  ROUNDED(x)
  return y;
}
void main() {
  fragColor = vec4(f(0.3));
}
