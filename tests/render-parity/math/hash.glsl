// Bits of the usual sine hash (tests/render-parity/README.md).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Argument();
  fragColor = Bits(fract(sin(dot(vec2(v, v * 0.61), vec2(12.9898, 78.233))) * 43758.5453));
}
