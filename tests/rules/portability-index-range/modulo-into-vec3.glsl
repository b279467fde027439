void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec3 col = vec3(0.0);
  for (int i = 0; i < 10; i++) col[i % 4] += 0.1;
  int k = int(fragCoord.x) % 4;
  fragColor = vec4(col, col[k]);
}
