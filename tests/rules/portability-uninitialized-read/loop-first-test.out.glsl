void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec3 p;
  float t = 0.0;
  for (int i = 0; ++i < 64 && length(p = vec3(fragCoord, 1.0) * t) < 9.0;) t += 0.1;
  vec3 q;
  float d = 9.0;
  for (int i = 0; i < 16 && d > 0.01; i++) { q = p * d; d *= 0.5; }
  vec3 r = vec3(0.0);
  for (int i = 0; i < int(iTime) && (r = q) != vec3(0.0); i++) {}
  fragColor = vec4(p + q + r, 1.0);
}
