// Bits of a vector built with a constant factor, divided by a constant: the browser
// multiplies by the reciprocal without merging it into the factor (tests/render-parity/README.md).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Argument();
  fragColor = Bits((vec2(v, v * 0.3) / 65534.0).y * 1000.0);
}
