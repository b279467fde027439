// Bits of products and quotients of a vector of literals with some components 0, NaN
// drawn as -1: the browser computes 0 * inf and 0 / 0 at run time (NaN), where Mesa folds
// a zero component's product or quotient to 0; a scalar 0 both fold
// (tests/render-parity/README.md).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float x = Argument();
  float zero = float(iFrame / 100000);  // 0 at run time
  float inf = 1.0 / zero;
  float row = floor(fragCoord.y / 8.0);
  float r = row < 1.0   ? (vec3(0, .03, .06) / (vec3(zero) + vec3(0, .3, 1))).x
            : row < 2.0 ? (vec2(0.0, 1.0) / vec2(zero)).x
            : row < 3.0 ? (vec3(inf) * vec3(0, 1, 1)).x
            : row < 4.0 ? (vec3(0, 1, 1) * vec3(x * inf)).x
            : row < 5.0 ? 0.0 * inf
            : row < 6.0 ? (vec3(0.5, 0, 2) * x).z
                        : x;
  fragColor = Bits(isnan(r) ? -1.0 : r);
}
