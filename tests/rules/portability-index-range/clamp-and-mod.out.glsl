void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec3 col = vec3(fragCoord / iResolution.xy, 0.5);
  int k = int(fragCoord.x);
  float a = col[clamp(k, 0, 3)];
  float b = col[int(mod(fragCoord.y, 4.0))];
  float c = col[(k & 7) >> 1];
  fragColor = vec4(a, b, c, 1.0);
}
