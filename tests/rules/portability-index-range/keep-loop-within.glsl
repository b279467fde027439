void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec3 col = vec3(0.0);
  for (int c = 0; c < 3; c++) col[c] = 0.1 * float(c);
  for (int c = 2; c >= 0; --c) col[c] += col[2 - c];
  for (int i = 0; i < 8; i += 2) col[i / 3] += 0.5;
  fragColor = vec4(col, 1.0);
}
