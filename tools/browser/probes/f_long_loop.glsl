// Probe (f): long loops. Each column counts iterations s (adding 1.0 per iteration) and
// shows s as bytes: R = floor(s / 65536), G = floor(s / 256) mod 256, B = s mod 256
// (100000 -> (1, 134, 160); 65535 -> (0, 255, 255); 65536 -> (1, 0, 0)).
// Columns (8 px wide), whole height:
//   0: for (int i = 0; i < N; i++) with N = 100000 from a uniform (99999 + int(iTime))
//   1: for (int i = 0; i < 100000; i++) (literal bound)
//   2: nested: 400 x 250 (literal bounds) = 100000
//   3: while (s < 100000.0) s += 1.0;
//   4: for (float x = 0.0; x < 70000.0; x += 1.0)
vec3 bytes(float s) {
  return vec3(floor(s / 65536.0), mod(floor(s / 256.0), 256.0), mod(s, 256.0)) / 255.0;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int column = int(fragCoord.x) / 8;
  float s = 0.0;
  if (column == 0) {
    int n = 99999 + int(iTime);
    for (int i = 0; i < n; i++) s += 1.0;
  } else if (column == 1) {
    for (int i = 0; i < 100000; i++) s += 1.0;
  } else if (column == 2) {
    for (int i = 0; i < 400; i++)
      for (int j = 0; j < 250; j++) s += 1.0;
  } else if (column == 3) {
    while (s < 100000.0) s += 1.0;
  } else if (column == 4) {
    for (float x = 0.0; x < 70000.0; x += 1.0) s += 1.0;
  }
  fragColor = vec4(bytes(s), 1.0);
}
