#define ACCUMULATOR vec4 acc;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  ACCUMULATOR
  acc += vec4(fragCoord.x / iResolution.x);
  fragColor = acc;
}
