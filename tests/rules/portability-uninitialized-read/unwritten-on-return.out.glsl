void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  fragColor = vec4(0.0);
  if (fragCoord.x < iResolution.x * 0.5) return;
  fragColor = vec4(0.2, 0.5, 0.8, 1.0);
}
