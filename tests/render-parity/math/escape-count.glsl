// Bits of an escape count: a perturbed Mandelbrot orbit (from iq's "Mandelbrot -
// perturbation") whose sums reach the picture only through the loop's break
// condition. Mesa regroups them unless that condition is kept exact too; a last-bit
// difference moves the step at which the orbit escapes (tests/render-parity/README.md).
vec2 cmul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  vec2 c = vec2(-1.1900443, 0.3043895);
  vec2 dc = vec2(Argument() * 1.5e-8, 0.5e-6 * iTime);
  vec2 z = vec2(0.0);
  vec2 dz = vec2(0.0);
  float n = -1.0;
  for (int i = 0; i < 2000; i++) {
    dz = cmul(2.0 * z + dz, dz) + dc;
    z = cmul(z, z) + c;
    if (dot(dz, dz) > 4.0) {
      n = float(i);
      break;
    }
  }
  fragColor = Bits(n);
}
