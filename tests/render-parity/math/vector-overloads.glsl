// Bits of the vector overloads of sin, cos, exp, exp2, log, log2, pow and mix, one
// component of one call per row (tests/render-parity/README.md): render writes them on
// whole vectors, which must give each component the bits of the float overload.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  pixel = fragCoord;
  float v = Argument();
  vec3 a = vec3(v, v * 0.37 + 1.0, -v * 1.3);
  vec3 p = abs(a) + 0.01;
  vec3 s = sin(a), c = cos(a.yzx), e = exp(a * 0.05), e2 = exp2(a.zxy * 0.07);
  vec3 l = log(p), l2 = log2(p.yzx), w = pow(p, vec3(0.4545, 2.2, 1.3));
  vec3 m = mix(a, a.zxy, vec3(0.3, fract(v), 0.9)), n = mix(a.yzx, vec3(0.25), fract(v * 3.0));
  vec2 s2 = sin(a.xz);
  vec4 e4 = exp(vec4(a, v) * 0.03);
  float row = mod(floor(pixel.y), 16.0);
  float r = row < 1.0   ? s.y
            : row < 2.0 ? s.z
            : row < 3.0 ? c.x
            : row < 4.0 ? c.z
            : row < 5.0 ? e.y
            : row < 6.0 ? e2.z
            : row < 7.0 ? l.x
            : row < 8.0 ? l2.y
            : row < 9.0 ? w.y
            : row < 10.0 ? w.z
            : row < 11.0 ? m.y
            : row < 12.0 ? m.z
            : row < 13.0 ? n.x
            : row < 14.0 ? s2.y
            : row < 15.0 ? e4.w
                         : e4.z;
  fragColor = Bits(r);
}
