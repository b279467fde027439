void brighten(inout vec3 c) { c = c * 1.5 + 0.1; }
void reset(inout vec3 c) { c = vec3(0.25); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec3 a;
  brighten(a);
  vec3 b;
  reset(b);
  fragColor = vec4(a + b, 1.0);
}
