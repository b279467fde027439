void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  float d;
  int n = 0;
  do {
    d = length(fragCoord) * float(n);
    n++;
  } while (n < int(iTime));
  vec3 col;
  for (int c = 0; c < 3; c++) col[c] = d * float(c);
  fragColor = vec4(col, 1.0);
}
