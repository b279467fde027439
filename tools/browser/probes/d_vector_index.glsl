// Probe (d): dynamic vector indexing out of range, index known only at run time:
// c = int(iResolution.x) / 9 = 7 at 64x64, m = -c = -7.
// Columns (8 px wide), whole height:
//   0: vec3 col = vec3(0); col[c] = 1.0;           -> col (0,0,255 if clamped to index 2)
//   1: col = vec3(0.2, 0.4, 0.6); vec3(col[c])      -> 153 if clamped to index 2
//   2: col = vec3(0); col[m] = 1.0;                 -> (255,0,0) if clamped to index 0
//   3: col = vec3(0.2, 0.4, 0.6); vec3(col[m])      -> 51 if clamped to index 0
//   4: mat3 mm = mat3(0.1..0.9); mm[c]              -> column 2 = (0.7, 0.8, 0.9) if clamped
//   5: vec4 q = vec4(0.2, 0.4, 0.6, 0.8); vec3(q[c]) -> 204 if clamped to index 3
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int column = int(fragCoord.x) / 8;
  int c = int(iResolution.x) / 9;
  int m = -c;
  vec3 v = vec3(0.0, 0.0, 1.0);
  if (column == 0) {
    vec3 col = vec3(0);
    col[c] = 1.0;
    v = col;
  } else if (column == 1) {
    vec3 col = vec3(0.2, 0.4, 0.6);
    v = vec3(col[c]);
  } else if (column == 2) {
    vec3 col = vec3(0);
    col[m] = 1.0;
    v = col;
  } else if (column == 3) {
    vec3 col = vec3(0.2, 0.4, 0.6);
    v = vec3(col[m]);
  } else if (column == 4) {
    mat3 mm = mat3(0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9);
    v = mm[c];
  } else if (column == 5) {
    vec4 q = vec4(0.2, 0.4, 0.6, 0.8);
    v = vec3(q[c]);
  }
  fragColor = vec4(v, 1.0);
}
