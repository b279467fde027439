// Common code of the math probes (tests/render-parity/math/*.glsl), as a ShaderToy
// Common tab: prepended to each probe by the test and by the reference command.
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
