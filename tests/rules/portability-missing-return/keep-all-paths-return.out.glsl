// Every path returns, discards or stays in an endless loop: nothing to report.
float always(int i) { if (i == 0) return 0.25; else return 0.5; }
float endless(float t) { for (;;) { t *= 0.5; if (t < 1.0) return t; } }
float looping(float t) { do { t *= 0.5; return t; } while (t > 1.0); }
float chosen(int i) {
  switch (i) {
  case 0: return 0.1;
  default: return 0.2;
  }
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int k = int(fragCoord.x) % 3;
  fragColor = vec4(always(k) + endless(fragCoord.y) + looping(iTime) + chosen(k));
}
