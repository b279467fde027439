// Bits of float(uint) of hashed values (tests/render-parity/README.md).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Argument();
  fragColor = Bits(float(uint(abs(v) * 4.1e7) * 2654435761u) / 4294967295.0);
}
