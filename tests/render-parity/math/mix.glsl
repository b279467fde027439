// Bits of mix with constant and varying weights (tests/render-parity/README.md).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Argument();
  fragColor = Bits(mix(v, 0.3, 0.77) + mix(v, v * 0.3 + 1.0, fract(v)));
}
