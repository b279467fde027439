// Bits of a vector built with a constant factor, divided by a constant: the browser
// multiplies by the reciprocal without merging it into the factor (tests/render-parity/README.md).
// Lays out the 32 bits of one float per pixel pair: even columns R, G, B = the
// three high bytes, odd columns R = the low byte. Arguments vary per pair and come
// from iTime (1.0), so no compiler can fold them.
vec2 pixel;
vec4 Bits(float r) {
  uint u = floatBitsToUint(r);
  if (mod(floor(pixel.x), 2.0) > 0.5) return vec4(float(u & 255u), 0.0, 0.0, 1.0) / 255.0;
  return vec4(float(u >> 24u), float((u >> 16u) & 255u), float((u >> 8u) & 255u), 255.0) / 255.0;
}
float Argument() {
  float i = floor(pixel.x * 0.5) + 32.0 * floor(pixel.y);
  return (i * 0.0491357 - 100.0) * iTime;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Argument();
  fragColor = Bits((vec2(v, v * 0.3) / 65534.0).y * 1000.0);
}
