// Probe (h), continued: the finite values some drivers give where GLSL leaves the result
// undefined (pow with x < 0, log with x < 0). one = iTime = 1 at run time.
// Columns (8 px wide), whole height:
//   0: vec3(pow(-2.0 * one, 0.5) / 2.0)   (sqrt(2)/2 -> 180 if pow uses |x|)
//   1: vec3(-log(-one) / 16.0)
//   2: vec3(log(-one) + 0.5)              (128 if log(-1) gives 0)
//   3: vec3(pow(-2.0 * one, 2.0) / 8.0)   (128 if pow(-2, 2) = 4)
//   4: vec3(pow(-8.0 * one, 1.0 / 3.0) / 4.0)  (128 if it gives |x|^(1/3) = 2)
//   5: vec3(exp2(log2(-one)) )             (log2 of a negative number, then exp2)
//   6: vec3(clamp(zero / zero, 0.0, 1.0) * 0.5 + 0.25)  (NaN through clamp: 64 if clamp
//      gives 0, 191 if 1, 0 if the NaN survives)
//   7: vec3(min(zero / zero, 0.5) + 0.25, max(zero / zero, 0.5) - 0.25, 0.0)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int column = int(fragCoord.x) / 8;
  float one = iTime;
  float zero = iTime - 1.0;
  vec3 v = vec3(0.0, 0.0, 1.0);
  if (column == 0) v = vec3(pow(-2.0 * one, 0.5) / 2.0);
  else if (column == 1) v = vec3(-log(-one) / 16.0);
  else if (column == 2) v = vec3(log(-one) + 0.5);
  else if (column == 3) v = vec3(pow(-2.0 * one, 2.0) / 8.0);
  else if (column == 4) v = vec3(pow(-8.0 * one, 1.0 / 3.0) / 4.0);
  else if (column == 5) v = vec3(exp2(log2(-one)));
  else if (column == 6) v = vec3(clamp(zero / zero, 0.0, 1.0) * 0.5 + 0.25);
  else if (column == 7) v = vec3(min(zero / zero, 0.5) + 0.25, max(zero / zero, 0.5) - 0.25, 0.0);
  fragColor = vec4(v, 1.0);
}
