void mainImage(out vec4 O, vec2 U) {
  for (float i = 0.; i < 9.; i++)
    O += .1 * sin(i * U.xyxy / iResolution.y + iTime);
}
