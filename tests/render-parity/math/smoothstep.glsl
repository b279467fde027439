// Bits of smoothstep with constant edges (tests/render-parity/README.md).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Argument();
  fragColor = Bits(smoothstep(-50.0, 70.0, v));
}
