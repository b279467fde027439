// Probe (h): what NaN and infinities draw. zero = iTime - 1 and one = iTime at run time.
// Columns (8 px wide). Top half (PNG y < 32): vec3(x) as drawn. Bottom half: a test:
// R = isnan(x), G = isinf(x), B = (x > 0.0).
//   0: x = 1.0 / zero          (+inf)
//   1: x = -1.0 / zero         (-inf)
//   2: x = zero / zero         (NaN)
//   3: x = sqrt(-one)          (NaN)
//   4: x = pow(-2.0 * one, 0.5) (undefined: NaN on most GPUs)
//   5: x = normalize(vec3(zero)).x  (0/0)
//   6: x = log(-one)           (NaN)
//   7: x = max(zero / zero, 0.5)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int column = int(fragCoord.x) / 8;
  bool top = fragCoord.y >= 32.0;
  float zero = iTime - 1.0;
  float one = iTime;
  float x = 0.25;
  if (column == 0) x = 1.0 / zero;
  else if (column == 1) x = -1.0 / zero;
  else if (column == 2) x = zero / zero;
  else if (column == 3) x = sqrt(-one);
  else if (column == 4) x = pow(-2.0 * one, 0.5);
  else if (column == 5) x = normalize(vec3(zero)).x;
  else if (column == 6) x = log(-one);
  else if (column == 7) x = max(zero / zero, 0.5);
  vec3 v = top ? vec3(x) : vec3(isnan(x) ? 1.0 : 0.0, isinf(x) ? 1.0 : 0.0, x > 0.0 ? 1.0 : 0.0);
  fragColor = vec4(v, 1.0);
}
