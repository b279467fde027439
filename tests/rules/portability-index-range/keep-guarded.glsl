const int N = 7;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 points[N];
  for (int i = 0; i < N; i++) points[i] = vec2(float(i), 0.0);
  vec3 col = vec3(0.0);
  for (int i = 0; i < 8; i++) {
    if (i > 2) break;
    col[i] = 1.0;
  }
  for (int i = 0; i < 8; i++) {
    if (i < 3) col[i] += 0.5;
    col.z += i < 3 ? col[i] : 0.0;
  }
  for (int i = 0; i < N; i++) {
    vec2 next = points[i == N - 1 ? 0 : i + 1];
    col.xy += next;
  }
  fragColor = vec4(col, 1.0);
}
