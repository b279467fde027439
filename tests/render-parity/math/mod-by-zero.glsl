// Bits of mod(x, y), NaN drawn as -1: where y is 0 (written, through a parameter, in one
// component of a vector) the browser computes x - y * floor(x / y) at run time and gets
// NaN, where Mesa folds it to x; by non-zero constants, written or through a parameter,
// the bits stay Chromium's with the divisor hidden from Mesa (tests/render-parity/README.md).
vec3 Rep(vec3 p, vec3 c) { return mod(p, c); }
float Reps(float p, float c) { return mod(p, c); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float x = Argument();
  float row = floor(fragCoord.y / 8.0);
  float r = row < 1.0   ? mod(x, 0.0)
            : row < 2.0 ? Reps(x, 0.0)
            : row < 3.0 ? Rep(vec3(x), vec3(3.5, 0.0, 0.0)).y
            : row < 4.0 ? mod(vec3(x), 0.0).y
            : row < 5.0 ? mod(x, 3.3)
            : row < 6.0 ? Rep(vec3(x), vec3(3.3, 0.7, 12.9)).z
                        : mod(x, 0.7);
  fragColor = Bits(isnan(r) ? -1.0 : r);
}
