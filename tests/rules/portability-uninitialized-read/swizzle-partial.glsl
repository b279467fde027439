void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec4 c;
  c.rgb = vec3(fragCoord / iResolution.xy, 0.5);
  fragColor = c;
}
