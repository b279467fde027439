// Bits of exp, exp2, log, log2 (tests/render-parity/README.md).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Argument();
  fragColor = Bits(exp(v * 0.05) + exp2(v * 0.07) + log(abs(v)) * log2(abs(v) + 2.0));
}
