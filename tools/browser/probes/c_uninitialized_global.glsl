// Probe (c): a global `vec3 g;` read before any write.
// Columns (8 px wide); top half value, bottom half test:
//   0: top g + 0.5 (128 per channel when g is 0)   bottom: green if g == vec3(0), red if not
//   1: top: global float array ga[3] read before write: vec3(ga[0], ga[1], ga[2]) + 0.5
//   2: top: global written in one pixel column only (x < 8) and read in this one: g2 + 0.5
vec3 g;
float ga[3];
vec3 g2;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int column = int(fragCoord.x) / 8;
  bool top = fragCoord.y >= 32.0;
  vec3 v = vec3(0.0, 0.0, 1.0);
  if (column < 1) g2 = vec3(0.9);
  if (column == 0) {
    v = top ? g + 0.5 : (g == vec3(0.0) ? vec3(0, 1, 0) : vec3(1, 0, 0));
  } else if (column == 1) {
    v = vec3(ga[0], ga[1], ga[2]) + 0.5;
  } else if (column == 2) {
    v = g2 + 0.5;
  }
  fragColor = vec4(v, 1.0);
}
