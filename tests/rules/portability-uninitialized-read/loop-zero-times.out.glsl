void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int steps = int(iTime) % 8;
  float last = 0.0;
  for (int i = 0; i < steps; i++) last = float(i) / 8.0;
  float w = 0.0;
  while (iMouse.z > float(steps)) { w = 1.0; break; }
  fragColor = vec4(last, w, 0.0, 1.0);
}
