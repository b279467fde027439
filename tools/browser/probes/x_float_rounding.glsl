// Extra probe: float rounding that hashes without sin (fract of products and sums, e.g.
// Dave Hoskins' hash12) amplify. Top half: does the compiler fuse a * b + c into one fma
// (one rounding instead of two)? Bottom half: in which order are sums evaluated?
// a = 1 + 2^-12 (from a uniform), a * a = 1 + 2^-11 + 2^-24 exactly; rounded to float that is
// 1 + 2^-11 (a tie, to even), so a * a - (1 + 2^-11) is 0 unfused and 2^-24 fused.
// Top half (PNG rows 0-31), columns 8 px wide:
//   0: (a * a + c) * 2^24 with c = -(1 + 2^-11): 255 if fused, 0 if not
//   1: the same written as two statements (p = a * a; p + c)
//   2: fract((a * a + c) * 2^24 * 0.5 + 0.25): 191 if fused, 64 if not
//   3: control, 0.5 -> 128
//   4: dot(vec2(a, 1), vec2(a, c)) * 2^24 (a * a + c inside dot): 255 if dot fuses
//   5: dot(vec3(a, 1, 0), vec3(a, c, 0)) * 2^24
//   6: length(vec2(a, 0)) - a, * 2^24 + 0.5 (sqrt(a * a) rounding): 128 if exact
//   7: (a * a) / a - a, * 2^24 + 0.5 (division rounding): 128 if exact
// Bottom half: the order in which dot() adds its products. B = 1e8 * iTime and
// N = -1e8 * iChannelTime[0] (both uniforms are 1, so N = -B, which the compiler cannot
// know); 1 is lost when added to B first. Left to right, ((x + y) + z) + w, gives:
//   0: dot(vec3(B, N, 1), vec3(1)) = 1 -> 255      1: dot(vec3(1, B, N), vec3(1)) = 0 -> 0
//   2: dot(vec4(B, N, 1, 0), vec4(1)) = 1 -> 255   3: dot(vec4(B, 1, N, 0), vec4(1)) = 0 -> 0
//   4: (1 + B) + N with scalars = 0 -> 0          5: 1 + (B + N) = 1 -> 255
//   6: like 1 but with -B written out: dot(vec3(1, B, -B), vec3(1)) (an algebraic
//      simplification B + -B = 0 gives 255)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int column = int(fragCoord.x) / 8;
  float a = iTime + 1.0 / 4096.0;
  float c = -(iTime + 1.0 / 2048.0);
  vec3 v = vec3(0.0, 0.0, 1.0);
  float B = 1e8 * iTime;
  float N = -1e8 * iChannelTime[0];
  if (fragCoord.y < 32.0) {
    if (column == 0) v = vec3(dot(vec3(B, N, 1.0), vec3(1.0)));
    else if (column == 1) v = vec3(dot(vec3(1.0, B, N), vec3(1.0)));
    else if (column == 2) v = vec3(dot(vec4(B, N, 1.0, 0.0), vec4(1.0)));
    else if (column == 3) v = vec3(dot(vec4(B, 1.0, N, 0.0), vec4(1.0)));
    else if (column == 4) v = vec3((1.0 + B) + N);
    else if (column == 5) v = vec3(1.0 + (B + N));
    else if (column == 6) v = vec3(dot(vec3(1.0, B, -B), vec3(1.0)));
  } else if (column == 0) {
    v = vec3((a * a + c) * 16777216.0);
  } else if (column == 1) {
    float p = a * a;
    v = vec3((p + c) * 16777216.0);
  } else if (column == 2) {
    v = vec3(fract((a * a + c) * 16777216.0 * 0.5 + 0.25));
  } else if (column == 3) {
    v = vec3(0.5);
  } else if (column == 4) {
    v = vec3(dot(vec2(a, 1.0), vec2(a, c)) * 16777216.0);
  } else if (column == 5) {
    v = vec3(dot(vec3(a, 1.0, 0.0), vec3(a, c, 0.0)) * 16777216.0);
  } else if (column == 6) {
    v = vec3((length(vec2(a, 0.0)) - a) * 16777216.0 + 0.5);
  } else if (column == 7) {
    v = vec3(((a * a) / a - a) * 16777216.0 + 0.5);
  }
  fragColor = vec4(v, 1.0);
}
