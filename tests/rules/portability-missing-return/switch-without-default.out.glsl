struct Material { bool transparent; float index; vec3 colour; };
Material pick(int object) {
  switch (object) {
  case 0:
    return Material(false, 0.0, vec3(0.0));
  case 1:
    return Material(true, 1.0 / 1.6, vec3(0.5));
  }
  return Material(false, 0.0, vec3(0.0));
}
float weight(int i) { if (i == 0) return 0.25; return 0.0; }
float always(int i) { if (i == 0) return 0.25; else return 0.5; }
float endless(float t) { for (;;) { t *= 0.5; if (t < 1.0) return t; } }
float leaves(float t) { while (true) { t *= 0.5; if (t < 1.0) break; if (t > 9.0) return 1.0; } return 0.0; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int k = int(fragCoord.x) % 3;
  fragColor = vec4(pick(k).colour + weight(k) + always(k) + endless(fragCoord.y) + leaves(iTime), 1.0);
}
