// Probe (g): an `out` parameter of a user function that the callee does not write.
// Columns (8 px wide), whole height; the caller's variable starts at 0.7 (179):
//   0: void f(out float x) {}                         -> v after f(v)
//   1: void f2(out float x, float k) { if (k > 2.0) x = 1.0; }, k = iTime = 1 -> v
//   2: void f3(out vec3 x) { x.r = 0.25; }; caller vec3(0.7)  -> (64, ?, ?)
//   3: control: void f4(inout float x) {} -> v (0.7 expected)
//   4: out struct parameter not written: struct S { float a; }; void f5(out S s) {} -> s.a
void f(out float x) {}
void f2(out float x, float k) { if (k > 2.0) x = 1.0; }
void f3(out vec3 x) { x.r = 0.25; }
void f4(inout float x) {}
struct S { float a; };
void f5(out S s) {}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int column = int(fragCoord.x) / 8;
  vec3 v = vec3(0.0, 0.0, 1.0);
  float x = 0.7;
  if (column == 0) {
    f(x);
    v = vec3(x);
  } else if (column == 1) {
    f2(x, iTime);
    v = vec3(x);
  } else if (column == 2) {
    vec3 y = vec3(0.7);
    f3(y);
    v = y;
  } else if (column == 3) {
    f4(x);
    v = vec3(x);
  } else if (column == 4) {
    S s = S(0.7);
    f5(s);
    v = vec3(s.a);
  }
  fragColor = vec4(v, 1.0);
}
