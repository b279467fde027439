// Bits of helpers given a constant zero: atan(0.0, x) is pi for x < 0 only if the zero
// keeps its sign on the way into the helper; atan(v, 0.7) for contrast
// (tests/render-parity/README.md).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = fract(Argument()) - 0.5;
  float kind = mod(floor(pixel.x * 0.5), 3.0);
  float r = kind < 1.0   ? atan(0.0, v)
            : kind < 2.0 ? atan(v * 0.0, -1.0)
                         : atan(v, 0.7);
  fragColor = Bits(r);
}
