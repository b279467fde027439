// Bits of sin beside clamp(0.0, 1.0, x / 0.5), which the browser's optimiser answers
// from its first two arguments (1.0): render rewrites both the clamp and the division
// in its third argument, and the two rewrites must not collide (each is applied).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Argument();
  float l = clamp(0.0, 1.0, (v - 1.0) / 0.5);
  fragColor = Bits(sin(v) * l);
}
