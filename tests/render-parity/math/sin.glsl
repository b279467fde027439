// Bits of sin and cos of -100..100 (tests/render-parity/README.md).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Argument();
  fragColor = Bits(sin(v) + cos(v * 0.37));
}
