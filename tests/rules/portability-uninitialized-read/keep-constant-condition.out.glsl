#define MODE 2
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec3 col;
  if (MODE == 1) col = vec3(1.0);
  else if (MODE == 2) col = vec3(0.5);
  float w[4];
  for (int i = 0; i < w.length(); i++) w[i] = float(i);
  fragColor = vec4(col, w[3]);
}
