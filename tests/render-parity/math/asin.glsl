// Bits of asin: the C library's asinf in SwiftShader (tests/render-parity/README.md).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Argument();
  fragColor = Bits(asin(fract(v) * 2.0 - 1.0) + asin(v * 0.0001));
}
