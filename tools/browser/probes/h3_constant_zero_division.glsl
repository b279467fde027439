// Probe (h), continued: division by a zero that is a compile-time constant after inlining
// (e.g. opSmoothUnion(a, b, 0.0) in SDF code) against a zero known only at run time.
// a = 0.3 and b = 9999 at run time; columns (8 px wide), whole height:
//   0: clamp(0.5 + 0.5 * (a - b) / k, 0, 1) with k = 0.0 through a function parameter
//      (-inf -> 0), G: the same with (b - a) (+inf -> 255)
//   1: the same with k = iTime - 1.0 (run-time zero)
//   2: vec3(1.0 / k) and vec3(-1.0 / k) in R and G, k = 0.0 through a parameter
//   3: opSmoothUnion(9999, 0.3, 0.0) (iq's polynomial smooth min with k = 0): 0.3 -> 76
//   4: smoothstep(z, z, 0.001) with z = iTime - 1 = 0 at run time (edge0 == edge1, undefined
//      in GLSL): R; G: smoothstep(z, z, -0.001); B: smoothstep(z, 0.0, 0.001)
//   5: the same with literal edges 0.0 (constant-folded by the compiler)
//   6: literal normalize(vec3(0.0)) (constant-folded): vec3(n.x + 0.5, isnan(n.x), 0.5)
//   7: literal 1.0 / 0.0 and 0.0 / 0.0 (constant-folded): R = isinf, G = isnan, B = 0.5
float hh(float d1, float d2, float k) { return clamp(0.5 + 0.5 * (d2 - d1) / k, 0.0, 1.0); }
float inv(float x, float k) { return x / k; }
float opSmoothUnion(float d1, float d2, float k) {
  float h = clamp(0.5 + 0.5 * (d2 - d1) / k, 0.0, 1.0);
  return mix(d2, d1, h) - k * h * (1.0 - h);
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int column = int(fragCoord.x) / 8;
  float a = 0.3 * iTime, b = 9999.0 * iTime;
  vec3 v = vec3(0.0, 0.0, 1.0);
  if (column == 0) v = vec3(hh(b, a, 0.0), hh(a, b, 0.0), 0.5);
  else if (column == 1) v = vec3(hh(b, a, iTime - 1.0), hh(a, b, iTime - 1.0), 0.5);
  else if (column == 2) v = vec3(inv(1.0 * iTime, 0.0), inv(-1.0 * iTime, 0.0), 0.5);
  else if (column == 3) v = vec3(opSmoothUnion(b, a, 0.0));
  else if (column == 4) {
    float z = iTime - 1.0;
    v = vec3(smoothstep(z, z, 0.001), smoothstep(z, z, -0.001), smoothstep(z, 0.0, 0.001));
  } else if (column == 5) {
    v = vec3(smoothstep(0.0, 0.0, 0.001), smoothstep(0.0, 0.0, -0.001), 0.5);
  } else if (column == 6) {
    vec3 n = normalize(vec3(0.0));
    v = vec3(n.x + 0.5, isnan(n.x) ? 1.0 : 0.0, 0.5);
  } else if (column == 7) {
    float pinf = 1.0 / 0.0;
    float qnan = 0.0 / 0.0;
    v = vec3(isinf(pinf) ? 1.0 : 0.0, isnan(qnan) ? 1.0 : 0.0, 0.5);
  }
  fragColor = vec4(v, 1.0);
}
