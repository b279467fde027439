// Bits of min, max, clamp, step and smoothstep given a NaN: SwiftShader's min and max
// return their second operand when either is NaN (tests/render-parity/README.md).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Argument();
  float n = uintBitsToFloat(floatBitsToUint(v) | 0x7fc00000u);  // a NaN no compiler folds
  float kind = mod(floor(pixel.x * 0.5), 8.0);
  float r = kind < 1.0 ? smoothstep(-1.0, 1.0, n)
          : kind < 2.0 ? clamp(n, 0.0, 1.0)
          : kind < 3.0 ? min(n, 1.0)
          : kind < 4.0 ? max(n, 0.0)
          : kind < 5.0 ? min(1.0, n)
          : kind < 6.0 ? max(0.0, n)
          : kind < 7.0 ? smoothstep(0.0, 1.0, n)
          : step(0.5, n);
  fragColor = Bits(r);
}
