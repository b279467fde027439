// Probe (b): an uninitialised local: `vec4 c; fragColor = c + 0.5;`.
// Columns (8 px wide); top half (y < 32 in the PNG) shows the value, bottom half a test:
//   0: top c + 0.5 (0.5 -> 128 when c is 0)       bottom: green if c == vec4(0), red if not
//   1: top: float t declared in a loop body, `t += 0.25` on 3 iterations, last t shown
//      (0.25 -> 64 when re-zeroed at each declaration, 0.75 -> 191 if it keeps its value)
//   2: top: uninitialised int k; vec3(float(k) + 0.5)          bottom: green if k == 0
//   3: top: uninitialised struct S { float a; vec2 b; } s; vec3(s.a, s.b) + 0.5
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int column = int(fragCoord.x) / 8;
  bool top = fragCoord.y >= 32.0;  // fragCoord.y grows upwards; the PNG's top half
  vec3 v = vec3(0.0, 0.0, 1.0);  // blue: column not used
  if (column == 0) {
    vec4 c;
    fragColor = c + 0.5;
    v = top ? fragColor.rgb : (c == vec4(0.0) ? vec3(0, 1, 0) : vec3(1, 0, 0));
  } else if (column == 1) {
    float last = -1.0;
    for (int i = 0; i < 3 + int(iTime) - 1; i++) {
      float t;
      t += 0.25;
      last = t;
    }
    v = vec3(last);
  } else if (column == 2) {
    int k;
    v = top ? vec3(float(k) + 0.5) : (k == 0 ? vec3(0, 1, 0) : vec3(1, 0, 0));
  } else if (column == 3) {
    struct S { float a; vec2 b; };
    S s;
    v = vec3(s.a, s.b) + 0.5;
  }
  fragColor = vec4(v, 1.0);
}
