// Bits of dot and length (tests/render-parity/README.md).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Argument();
  fragColor = Bits(dot(vec3(v, v * 0.37, 1.3), vec3(0.71, v * 1.1, v)) + length(vec3(v, 1.3, v * 0.37)));
}
