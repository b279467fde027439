// Probe (e): `float a[4]; a[i]` with i out of range at run time, for read and for write.
// a = {0.1, 0.2, 0.3, 0.4}; i = int(iResolution.x) / 9 = 7, n = -1.
// Columns (8 px wide), whole height:
//   0: vec3(a[7])                               -> 102 if clamped to a[3]
//   1: a[7] = 0.9; vec3(a[3], a[0], a[2])       -> R 230 if the write went to a[3]
//   2: vec3(a[-1])                              -> 26 if clamped to a[0]
//   3: a[-1] = 0.9; vec3(a[0], a[1], a[3])      -> R 230 if the write went to a[0]
//   4: vec4 arr[2] = {(.1,.2,.3,1), (.5,.6,.7,1)}; arr[7].rgb -> (128,153,179) if clamped to arr[1]
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int column = int(fragCoord.x) / 8;
  int i = int(iResolution.x) / 9;
  int n = int(iTime) - 2;
  float a[4];
  a[0] = 0.1; a[1] = 0.2; a[2] = 0.3; a[3] = 0.4;
  vec3 v = vec3(0.0, 0.0, 1.0);
  if (column == 0) {
    v = vec3(a[i]);
  } else if (column == 1) {
    a[i] = 0.9;
    v = vec3(a[3], a[0], a[2]);
  } else if (column == 2) {
    v = vec3(a[n]);
  } else if (column == 3) {
    a[n] = 0.9;
    v = vec3(a[0], a[1], a[3]);
  } else if (column == 4) {
    vec4 arr[2] = vec4[2](vec4(0.1, 0.2, 0.3, 1.0), vec4(0.5, 0.6, 0.7, 1.0));
    v = arr[i].rgb;
  }
  fragColor = vec4(v, 1.0);
}
