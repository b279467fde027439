// Bits of atan with one and two arguments (tests/render-parity/README.md).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Argument();
  fragColor = Bits(atan(v * 0.1) + atan(v, 1.7));
}
