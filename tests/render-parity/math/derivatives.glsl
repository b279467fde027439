// Bits of dFdx, dFdy and fwidth: Chromium's are coarse (one value per 2x2 quad, from
// its first row and column) and fwidth of a constant is -0.0, so 1.0 / fwidth(c) is
// -inf (tests/render-parity/README.md). Values are exact integers, quads stay whole.
float Value() {
  vec2 p = floor(pixel);
  return p.x * p.y * 13.0 + p.y * p.y * 37.0 + p.x * p.x * 71.0 + iTime;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Value();
  float c = floor(fragCoord.x / 16.0) - 1.5;
  float kind = mod(floor(fragCoord.y * 0.5), 4.0);
  float r = kind < 1.0   ? dFdx(v)
            : kind < 2.0 ? dFdy(v)
            : kind < 3.0 ? fwidth(v)
                         : c / fwidth(c);
  fragColor = Bits(r);
}
