void polar(in vec2 p, out float radius, out float angle) {
  radius = length(p);
  angle = atan(p.y, p.x);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  float r, a;
  polar(fragCoord / iResolution.xy - 0.5, r, a);
  float whole;
  float part = modf(a * 3.0, whole);
  fragColor = vec4(r, part, whole, 1.0);
}
