// Bits of fract: SwiftShader's is min(x - floor(x), 0.99999994), which never reaches 1.0
// (tiny negative arguments) and, by minps's rule, gives 0.99999994 for a NaN, where
// llvmpipe's is NaN (tests/render-parity/README.md).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float x = Argument();
  float zero = float(iFrame / 100000);  // 0 at run time
  float row = floor(fragCoord.y / 8.0);
  float r = row < 1.0   ? fract(x)
            : row < 2.0 ? fract(x * 1e-9 - 1e-12)
            : row < 3.0 ? fract(zero / zero)
            : row < 4.0 ? fract(vec3(x, zero / zero, -x * 1e-10)).y
            : row < 5.0 ? fract(vec2(-x * 1e-10, x)).x
                        : fract(x * 437.5453);
  fragColor = Bits(r);
}
