// Bits of divisions by zeros that only the driver's own propagation sees (a struct
// member and a global set in another function), of a literal zero and of a zero of
// either sign: the browser gives +-inf or NaN (tests/render-parity/README.md).
struct Blur {
  vec2 width;
};
Blur blur;
float zero_global;
void Init() {
  blur = Blur(vec2(0.0, 1.0));
  zero_global = 0.0;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  Init();
  pixel = fragCoord;
  float v = fract(Argument()) - 0.5;
  float kind = mod(floor(pixel.x * 0.5), 5.0);
  float r = kind < 1.0   ? v / blur.width.x
            : kind < 2.0 ? clamp(-v / zero_global + blur.width.y, 0.0, 1.0)
            : kind < 3.0 ? (vec2(v, 1.0) / vec2(blur.width.x, 2.0)).x
            : kind < 4.0 ? v / 0.0
                         : 1.0 / (v * 0.0);
  fragColor = Bits(r);
}
