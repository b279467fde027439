void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec3 col = vec3(0.0);
  for (int c = 0; c < 8; c++) col[c] = 0.1 * float(c);
  fragColor = vec4(col, 1.0);
}
