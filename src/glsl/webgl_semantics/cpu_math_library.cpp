// Each definition follows SwiftShader's code (src/Pipeline/ShaderCore.cpp and
// SpirvShaderGLSLstd450.cpp) operation by operation; constants are the float values
// of its literals. llvmpipe then computes the same bits as Chromium: on 2,048
// arguments per function (tests/render-parity/math, BrowserParity.MathHasChromiumsBits)
// every helper matches Chromium 156 bit for bit, where llvmpipe's own built-ins differ
// in the last bits (sin and cos by about 800 ulp). `tanh` departs where noted.
#include "glsl/webgl_semantics/cpu_math_library.h"

#include "glsl/webgl_semantics/cpu_math_helpers.h"

namespace shaderport::glsl {

// `S(name)` below is "shaderport_name", `Z` the opaque zero: subtracted from a
// constant that the caller's constants must not be folded into (Mesa turns
// `(x * 0.5) * 1.44` into `x * 0.72`; SwiftShader multiplies twice). One line each.
const std::array<Helper, 37>& CpuMathHelpers() {
  static const std::array<Helper, 37> helpers = {{
      // Sin5: A x^5 + B x^3 + C x on [-1/4, 1/4] (argument in turns).
      {"sin5",
       Shape::kInternal,
       {},
       "float S(sin5)(float x) { float x2 = x * x; return ((74.43889 * x2 + -41.16937) * x2 + "
       "6.2823086) * x; }",
       {},
       "@ S(sin5)(@ x) { @ x2 = x * x; return ((74.43889 * x2 + -41.16937) * x2 + 6.2823086) * x; "
       "}"},
      {"sin",
       Shape::kUnary,
       {"sin5"},
       "float S(sin)(float x) { float t = x * (-0.15915494 - Z) + 0.25; return S(sin5)(0.25 - "
       "abs(t - roundEven(t))); }",
       {},
       "@ S(sin)(@ x) { @ t = x * (-0.15915494 - Z) + 0.25; return S(sin5)(0.25 - abs(t - "
       "roundEven(t))); }"},
      {"cos",
       Shape::kUnary,
       {"sin5"},
       "float S(cos)(float x) { float t = x * (0.15915494 - Z); return S(sin5)(0.25 - abs(t - "
       "roundEven(t))); }",
       {},
       "@ S(cos)(@ x) { @ t = x * (0.15915494 - Z); return S(sin5)(0.25 - abs(t - "
       "roundEven(t))); }"},
      {"tan",
       Shape::kUnary,
       {"sin", "cos"},
       "float S(tan)(float x) { return S(sin)(x) / S(cos)(x); }"},
      // Chromium builds SwiftShader with its legacy exp2/log2 (SWIFTSHADER_LEGACY_PRECISION).
      {"exp2",
       Shape::kUnary,
       {},
       "float S(exp2)(float x) { float x0 = max(min(x, 128.0), -126.99999); int i = "
       "int(roundEven(x0 - 0.5)); float f = x0 - float(i); float p = intBitsToFloat(989206789); "
       "p = p * f + intBitsToFloat(1007896582); p = p * f + intBitsToFloat(1030007331); p = p * f "
       "+ intBitsToFloat(1047915220); p = p * f + intBitsToFloat(1060205179); p = p * f + 1.0; "
       "return intBitsToFloat((i + 127) << 23) * p; }",
       {},
       "@ S(exp2)(@ x) { @ x0 = max(min(x, 128.0), -126.99999); $ i = $(roundEven(x0 - 0.5)); @ f "
       "= x0 - @(i); @ p = @(intBitsToFloat(989206789)); p = p * f + intBitsToFloat(1007896582); "
       "p = p * f + intBitsToFloat(1030007331); p = p * f + intBitsToFloat(1047915220); p = p * f "
       "+ intBitsToFloat(1060205179); p = p * f + 1.0; return intBitsToFloat((i + 127) << 23) * "
       "p; }"},
      {"log2",
       Shape::kUnary,
       {},
       "float S(log2)(float x) { int b = floatBitsToInt(x); float e = uintBitsToFloat(uint(b & "
       "2139095040) >> 8u | 1065353216u); e = (e - 1.4960938) * 256.0; float m = "
       "intBitsToFloat(b & 8388607 | 1065353216); float p = (0.095428176 * m + 0.47779095) * m + "
       "0.19782813; float q = ((0.016618466 * m + 0.20350508) * m + 0.273829) * m + 0.04049669; "
       "e += (m - 1.0) * (p / q); return mix(e, x, b == 2139095040); }",
       {},
       "@ S(log2)(@ x) { $ b = floatBitsToInt(x); @ e = uintBitsToFloat(%(b & 2139095040) >> 8u | "
       "1065353216u); e = (e - 1.4960938) * 256.0; @ m = intBitsToFloat(b & 8388607 | "
       "1065353216); @ p = (0.095428176 * m + 0.47779095) * m + 0.19782813; @ q = ((0.016618466 * "
       "m + 0.20350508) * m + 0.273829) * m + 0.04049669; e += (m - 1.0) * (p / q); return "
       "mix(e, x, equal(b, $(2139095040))); }"},
      {"exp",
       Shape::kUnary,
       {"exp2"},
       "float S(exp)(float x) { return S(exp2)((1.442695 - Z) * x); }",
       {},
       "@ S(exp)(@ x) { return S(exp2)((1.442695 - Z) * x); }"},
      {"log",
       Shape::kUnary,
       {"log2"},
       "float S(log)(float x) { return (0.6931472 - Z) * S(log2)(x); }",
       {},
       "@ S(log)(@ x) { return (0.6931472 - Z) * S(log2)(x); }"},
      {"pow",
       Shape::kBinary,
       {"exp2", "log2"},
       "float S(pow)(float x, float y) { return S(exp2)(S(log2)(x) * y); }",
       {},
       "@ S(pow)(@ x, @ y) { return S(exp2)(S(log2)(x) * y); }"},
      {"sinh",
       Shape::kUnary,
       {"exp"},
       "float S(sinh)(float x) { return (S(exp)(x) - S(exp)(-x)) * 0.5; }"},
      {"cosh",
       Shape::kUnary,
       {"exp"},
       "float S(cosh)(float x) { return (S(exp)(x) + S(exp)(-x)) * 0.5; }"},
      // Past |x| = 88 SwiftShader's formula gives inf / inf = NaN; there render gives the
      // +-1 it tends to (a multipass project reached such values in render but not in
      // Chromium's page, whose picture is finite there; not understood yet).
      {"tanh",
       Shape::kUnary,
       {"exp"},
       "float S(tanh)(float x) { if (abs(x) > 88.0) return sign(x); float a = S(exp)(x); float b "
       "= S(exp)(-x); return (a - b) / (a + b); }"},
      {"asinh",
       Shape::kUnary,
       {"log"},
       "float S(asinh)(float x) { return S(log)(x + sqrt(x * x + 1.0)); }"},
      {"acosh",
       Shape::kUnary,
       {"log"},
       "float S(acosh)(float x) { return S(log)(x + sqrt(x + 1.0) * sqrt(x - 1.0)); }"},
      {"atanh",
       Shape::kUnary,
       {"log"},
       "float S(atanh)(float x) { return S(log)((1.0 + x) / (1.0 - x)) * 0.5; }"},
      // asin is the C library's asinf (glibc's float version: a polynomial in x^2, and
      // for |x| >= 0.5 one in (1 - |x|) / 2 with a split square root).
      {"asin",
       Shape::kUnary,
       {},
       "float S(asin)(float x) { int hx = floatBitsToInt(x); int ix = hx & 2147483647; if (ix "
       "== 1065353216) return x * (1.5707964 - Z) + x * (-4.371139e-08 - Z); if (ix > "
       "1065353216) return intBitsToFloat(-4194304); if (ix < 1056964608) { if (ix < 838860800) "
       "return x; float t = x * x; float w = t * (0.16666752 + t * (0.074952975 + t * "
       "(0.045470376 + t * (0.024179514 + t * 0.042166308)))); return x + x * w; } float t = "
       "(1.0 - abs(x)) * 0.5; float p = t * (0.16666752 + t * (0.074952975 + t * (0.045470376 + "
       "t * (0.024179514 + t * 0.042166308)))); float s = sqrt(t); float r; if (ix >= "
       "1064933786) { r = (1.5707964 - Z) - (2.0 * (s + s * p) - (-4.371139e-08 - Z)); } else { "
       "float w = intBitsToFloat(floatBitsToInt(s) & -4096); float c = (t - w * w) / (s + w); "
       "float q = 2.0 * s * p - ((-4.371139e-08 - Z) - 2.0 * c); r = (0.7853982 - Z) - (q - "
       "((0.7853982 - Z) - 2.0 * w)); } return hx > 0 ? r : -r; }"},
      // acos uses a 4-term polynomial even at highp.
      {"acos",
       Shape::kUnary,
       {},
       "float S(acos)(float x) { float a = abs(x); float r = 1.5707964 - sqrt(1.0 - a) * "
       "(1.5707288 + a * (-0.2121144 + a * (0.074261 + a * -0.0187293))); return 1.5707964 - "
       "intBitsToFloat(floatBitsToInt(r) ^ (floatBitsToInt(x) & int(0x80000000u))); }"},
      {"atan01",
       Shape::kInternal,
       {},
       "float S(atan01)(float x) { float x2 = x * x; return x + x * (x2 * (-0.33333147 + x2 * "
       "(0.19993551 + x2 * (-0.142089 + x2 * (0.10656264 + x2 * (-0.07528964 + x2 * "
       "(0.042909615 + x2 * (-0.016165737 + x2 * 0.0028662258)))))))); }"},
      // atan(y_over_x) and atan(y, x): the same name, told apart by arity. Selects by
      // mix (every operand is computed anyway; `?:` costs Mesa a branch each).
      {"atan",
       Shape::kUnary,
       {"atan01"},
       "float S(atan)(float x) { float a = abs(x); bool o = !(a < 1.0); float t = "
       "S(atan01)(mix(a, 1.0 / a, o)); float r = mix(t, 1.5707964 - t, o); return "
       "intBitsToFloat(floatBitsToInt(r) ^ (floatBitsToInt(x) & int(0x80000000u))); }"
       " float S(atan)(float y, float x) { bool s = y < 0.0; float theta = mix(0.0, -3.1415927, "
       "s); float x0 = intBitsToFloat((floatBitsToInt(y) & int(0x80000000u)) ^ "
       "floatBitsToInt(x)); float y0 = abs(y); bool q = x0 < 0.0; theta += mix(0.0, 1.5707964, "
       "q); float x1 = mix(x0, y0, q); float y1 = mix(y0, -x0, q); bool o = !(y1 < x1); float x2 "
       "= mix(x1, y1, o); float y2 = mix(y1, x1, o); bool inf_y = isinf(y2); float t = "
       "S(atan01)(y2 / x2); theta += mix(mix(0.0, 0.7853982, inf_y), mix(t, 1.5707964 - t, o), "
       "x2 != 0.0 && !inf_y); return mix(theta, -t, s && q && o && !inf_y); }"},
      // SwiftShader's derivatives are coarse: dFdx is the top row's difference and dFdy
      // the left column's for the whole 2x2 quad; llvmpipe's are per row and per column.
      // In the odd row, v - dFdy(v) is the even row's value (in the odd column,
      // v - dFdx(v) the even column's), exactly when the difference is. fwidth =
      // |dFdx| + |dFdy| of those, and -0.0 where both are 0 (measured in Chromium:
      // 1.0 / fwidth(c) is -inf there).
      // clamp(x, lo, hi) that the optimiser answers from x and one bound (see
      // cpu_browser_math.cpp): the call keeps every argument, and returns that bound.
      {"clamp_lo",
       Shape::kInternal,
       {},
       "float S(clamp_lo)(float x, float lo, float hi) { return lo; }"},
      {"clamp_hi",
       Shape::kInternal,
       {},
       "float S(clamp_hi)(float x, float lo, float hi) { return hi; }"},
      {"dFdx",
       Shape::kUnary,
       {},
       "float S(dFdx)(float v) { return dFdx(mod(floor(gl_FragCoord.y), 2.0) > 0.5 ? v - dFdy(v) "
       ": v); }"},
      {"dFdy",
       Shape::kUnary,
       {},
       "float S(dFdy)(float v) { return dFdy(mod(floor(gl_FragCoord.x), 2.0) > 0.5 ? v - dFdx(v) "
       ": v); }"},
      {"fwidth",
       Shape::kUnary,
       {"dFdx", "dFdy"},
       "float S(fwidth)(float v) { float f = abs(S(dFdx)(v)) + abs(S(dFdy)(v)); return f == 0.0 ? "
       "-f : f; }"},
      // SwiftShader's fract is min(x - floor(x), 0x3F7FFFFF): never 1.0, and with
      // minps's rule 0.99999994 for a NaN (llvmpipe gives NaN, which then blackens
      // what a browser draws; measured, ShaderToy 7ttGDn). The comparison is xored with
      // an opaque false, as in min below.
      {"fract",
       Shape::kUnary,
       {},
       "float S(fract)(float x) { float f = x - floor(x); float c = intBitsToFloat(1065353215); "
       "return mix(c, f, (f < c) != (Z < 0.0)); }",
       {},
       "@ S(fract)(@ x) { @ f = x - floor(x); @ c = @(intBitsToFloat(1065353215)); return mix(c, "
       "f, notEqual(lessThan(f, c), b@(Z < 0.0))); }"},
      // SwiftShader's min and max are x86's minps/maxps: the second operand when either
      // is NaN (min(1.0, NaN) is NaN, llvmpipe gives 1.0). The comparison is xored
      // with an opaque false: Mesa turns `a < b ? a : b` back into its own fmin. A
      // select by mix, not `?:`, which Mesa compiles as a branch first (a tenth of the
      // AO template's compile); vectors compare all components at once.
      {"min",
       Shape::kMinMax,
       {},
       "float S(min)(float a, float b) { return mix(b, a, (a < b) != (Z < 0.0)); }",
       {},
       "@ S(min)(@ a0, @ a1) { return mix(a1, a0, notEqual(lessThan(a0, a1), b@(Z < 0.0))); } @ "
       "S(min)(@ a0, float a1) { @ b = @(a1); return mix(b, a0, notEqual(lessThan(a0, b), b@(Z < "
       "0.0))); }"},
      {"max",
       Shape::kMinMax,
       {},
       "float S(max)(float a, float b) { return mix(b, a, (a > b) != (Z < 0.0)); }",
       {},
       "@ S(max)(@ a0, @ a1) { return mix(a1, a0, notEqual(greaterThan(a0, a1), b@(Z < 0.0))); } @ "
       "S(max)(@ a0, float a1) { @ b = @(a1); return mix(b, a0, notEqual(greaterThan(a0, b), b@(Z "
       "< "
       "0.0))); }"},
      {"mix",
       Shape::kMix,
       {},
       "float S(mix)(float x, float y, float a) { return a * (y - x) + x; }",
       {},
       "@ S(mix)(@ x, @ y, @ a) { return a * (y - x) + x; } @ S(mix)(@ x, @ y, float a) { return "
       "a * (y - x) + x; }"},
      // dot: x0 * y0, then MulAdd(xi, yi, d) for each further component.
      {"dot",
       Shape::kReduction,
       {},
       "float S(dot)(@ x, @ y) { float d = x.x * y.x;# d = x.# * y.# + d; return d; }",
       "float S(dot)(float x, float y) { return x * y; }"},
      // length and normalize spell dot's sum out: the same operations without a call,
      // which costs Mesa's compiler as much as the arithmetic.
      {"length",
       Shape::kReduction,
       {},
       "float S(length)(@ x) { float d = x.x * x.x;# d = x.# * x.# + d; return sqrt(d); }",
       "float S(length)(float x) { return sqrt(x * x); }"},
      {"distance",
       Shape::kReduction,
       {},
       "float S(distance)(@ p, @ q) { @ v = p - q; float d = v.x * v.x;# d += v.# * v.#; "
       "return sqrt(d); }",
       "float S(distance)(float p, float q) { float v = p - q; return sqrt(v * v); }"},
      // 1 / sqrt(d), not inversesqrt(d): SwiftShader divides.
      {"normalize",
       Shape::kGeometric,
       {},
       "@ S(normalize)(@ x) { float d = x.x * x.x;# d = x.# * x.# + d; float r = 1.0 / (sqrt(d) "
       "- Z); return r * x; }",
       "float S(normalize)(float x) { float r = 1.0 / (sqrt(x * x) - Z); return r * x; }"},
      {"reflect",
       Shape::kGeometric,
       {"dot"},
       "@ S(reflect)(@ i, @ n) { float d = S(dot)(i, n); return i - 2.0 * d * n; }"},
      {"refract",
       Shape::kGeometric,
       {"dot"},
       "@ S(refract)(@ i, @ n, float eta) { float d = S(dot)(i, n); float k = 1.0 - eta * eta * "
       "(1.0 - d * d); float t = eta * d + sqrt(k); return k < 0.0 ? @(0.0) : eta * i - t * n; "
       "}"},
      {"faceforward",
       Shape::kGeometric,
       {"dot"},
       "@ S(faceforward)(@ n, @ i, @ r) { return S(dot)(i, r) < 0.0 ? n : -n; }"},
      // float(uint): the low 31 bits converted, then 2^31 added (two roundings).
      {"u2f",
       Shape::kFromUint,
       {},
       "float S(u2f)(uint x) { return float(int(x & 2147483647u)) + ((x >> 31u) != 0u ? "
       "2147483648.0 : 0.0); }"},
      {"cross",
       Shape::kInternal,
       {},
       "vec3 S(cross)(vec3 a, vec3 b) { return vec3(a.y * b.z - b.y * a.z, a.z * b.x - b.z * "
       "a.x, a.x * b.y - b.x * a.y); }"},
  }};
  return helpers;
}

const Helper* FindCpuMathHelper(std::string_view name) {
  for (const Helper& helper : CpuMathHelpers()) {
    if (helper.builtin == name) return &helper;
  }
  return nullptr;
}

bool HasCpuMathDefinition(std::string_view builtin) {
  const Helper* helper = FindCpuMathHelper(builtin);
  return helper != nullptr && (helper->shape != Shape::kInternal || builtin == "cross");
}

std::string OpaqueSelect(std::string_view type, std::string_view zero, std::string_view if_false,
                         std::string_view if_true) {
  const std::string condition = std::string(zero) + " < 0.0";
  if (type == "float") {
    return "mix(" + std::string(if_false) + ", " + std::string(if_true) + ", " + condition + ")";
  }
  if (type == "vec2" || type == "vec3" || type == "vec4") {
    return "mix(" + std::string(if_false) + ", " + std::string(if_true) + ", b" +
           std::string(type) + "(" + condition + "))";
  }
  return "(" + condition + " ? " + std::string(if_true) + " : " + std::string(if_false) + ")";
}

std::string CpuMathHelperName(std::string_view builtin) {
  return "shaderport_" + std::string(builtin);
}

}  // namespace shaderport::glsl
