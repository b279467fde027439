void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec4 c = vec4(0.0);
  c.rgb = vec3(fragCoord / iResolution.xy, 0.5);
  fragColor = c;
}
