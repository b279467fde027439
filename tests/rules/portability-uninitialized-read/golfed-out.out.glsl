void mainImage(out vec4 O, vec2 U) {
  O = vec4(0.0);
  for (float i = 0.; i < 9.; i++)
    O += .1 * sin(i * U.xyxy / iResolution.y + iTime);
}
