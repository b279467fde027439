void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  fragColor.rgb = vec3(fragCoord / iResolution.xy, 0.5);
  fragColor.a = 1.0;
  vec2 p;
  p.x = fragCoord.x;
  float x = p.x;
  p.y = x;
  fragColor.xy *= p;
}
