void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec3 col = vec3(fragCoord / iResolution.xy, 0.5);
  int k = int(iTime);
  fragColor = vec4(col[k], col[k % 3], col[min(k, 2)], 1.0);
}
