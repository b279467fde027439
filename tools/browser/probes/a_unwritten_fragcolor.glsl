// Probe (a): mainImage never writes fragColor. The site's main() passes vec4(1e20) as the
// argument of the `out vec4 fragColor` parameter and then draws vec4(color.xyz, 1.0).
// Columns (8 px wide, x = 8*i .. 8*i+7), same in top and bottom halves:
//   0: fragColor never written
//   1: only fragColor.r = 0.25 written (g and b show what the other components hold)
//   2: control: fragColor = vec4(0.25, 0.5, 0.75, 1.0)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int column = int(fragCoord.x) / 8;
  if (column == 1) {
    fragColor.r = 0.25;
  } else if (column == 2) {
    fragColor = vec4(0.25, 0.5, 0.75, 1.0);
  }
}
