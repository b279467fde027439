// Bits of division by a constant (a multiplication by its reciprocal) (tests/render-parity/README.md).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Argument();
  fragColor = Bits(v / 3.3 + v / vec2(1.7, 6.1).y);
}
