// A non-void function that runs off its end (a switch without default, an if
// without else) returns zero in the browser; GLSL leaves it undefined.
struct Material { float shine; vec3 colour; };

float Weight(int i) { if (i == 0) return 0.25; }
vec3 Tint(int i) { switch (i) { case 0: return vec3(0.25); } }
Material Pick(int i) { if (i == 0) return Material(0.25, vec3(0.5)); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int k = int(iTime) + int(fragCoord.x > 32.0);  // 1 or 2: never the case written
  fragColor = vec4(Weight(k) + 0.5, Tint(k).x + 0.25, Pick(k).shine + Pick(k).colour.y + 0.1, 1.0);
}
