// Bits of a sum that Mesa's optimiser regroups: it moves a constant up an addition
// chain, (a * a - b * b) + c into (a * a + c) - b * b; Chromium adds as written
// (tests/render-parity/README.md).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Argument() * 0.01;
  float w = v * 0.25 + 0.3043895 * iTime;
  fragColor = Bits((v * v - w * w) + -1.1900443);
}
