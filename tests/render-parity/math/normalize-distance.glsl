// Bits of normalize and distance (tests/render-parity/README.md).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Argument();
  fragColor = Bits(normalize(vec3(v, v * 0.37, 1.3)).y + distance(vec2(v, 1.0), vec2(0.3, v * 0.2)));
}
