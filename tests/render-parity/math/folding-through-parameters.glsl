// Bits of built-ins whose arguments are constants only through a parameter: the
// browser's optimiser folds tan, sin and pow of a constant but not radians, abs, floor
// or fract, so tan(radians(p)) is computed at run time with SwiftShader's tan, while
// tan(radians(45.0)) is folded whole by ANGLE (tests/render-parity/README.md).
float TanOfRadians(float p) { return tan(radians(p)); }
float SinOfAbs(float p) { return sin(abs(p)); }
float CosOfFract(float p) { return cos(fract(p)); }
float PowOfFloor(float p) { return pow(floor(p), 0.37); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float row = floor(fragCoord.y / 8.0);
  float r = row < 1.0   ? TanOfRadians(45.0)
            : row < 2.0 ? SinOfAbs(-2.3)
            : row < 3.0 ? CosOfFract(7.77)
            : row < 4.0 ? PowOfFloor(9.5)
            : row < 5.0 ? tan(radians(45.0))
                        : Argument();
  fragColor = Bits(r);
}
