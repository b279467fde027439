// Each definition follows SwiftShader's code (src/Pipeline/ShaderCore.cpp and
// SpirvShaderGLSLstd450.cpp) operation by operation; constants are the float values
// of its literals. llvmpipe then computes the same bits as Chromium: on 2,048
// arguments per function (tests/render-parity/math, BrowserParity.MathHasChromiumsBits)
// every helper matches Chromium 156 bit for bit, where llvmpipe's own built-ins differ
// in the last bits (sin and cos by about 800 ulp). `tanh` departs where noted.
#include "glsl/webgl_semantics/cpu_math_library.h"

#include <array>
#include <cctype>
#include <vector>

namespace shaderport::glsl {
namespace {

// How the helper's float definition extends to vectors.
enum class Shape : uint8_t {
  kUnary,      // genType f(genType): componentwise
  kBinary,     // genType f(genType, genType): componentwise
  kMinMax,     // genType f(genType, genType) and (genType, float): componentwise
  kMix,        // genType f(genType, genType, genType) and (genType, genType, float)
  kReduction,  // float f(genType[, genType]): written for each size below
  kGeometric,  // genType f(genType, ...): written for each size below
  kInternal,   // float only, called by other helpers
  kFromUint,   // float f(uint) and vecN f(uvecN): componentwise
};

struct Helper {
  std::string_view builtin;  // GLSL name, or an internal name
  Shape shape;
  std::vector<std::string_view> calls;  // other helpers used
  // float definition; for kReduction/kGeometric: `@` is the type, `#` the body part
  // that repeats per component (see ForSize).
  std::string_view text;
  std::string_view float_text = {};  // kReduction: the float overload (no swizzles on floats)
};

// `S(name)` below is "shaderport_name", `Z` the opaque zero: subtracted from a
// constant that the caller's constants must not be folded into (Mesa turns
// `(x * 0.5) * 1.44` into `x * 0.72`; SwiftShader multiplies twice). One line each.
const std::array<Helper, 33>& Helpers() {
  static const std::array<Helper, 33> helpers = {{
      // Sin5: A x^5 + B x^3 + C x on [-1/4, 1/4] (argument in turns).
      {"sin5",
       Shape::kInternal,
       {},
       "float S(sin5)(float x) { float x2 = x * x; return ((74.43889 * x2 + -41.16937) * x2 + "
       "6.2823086) * x; }"},
      {"sin",
       Shape::kUnary,
       {"sin5"},
       "float S(sin)(float x) { float t = x * (-0.15915494 - Z) + 0.25; return S(sin5)(0.25 - "
       "abs(t - roundEven(t))); }"},
      {"cos",
       Shape::kUnary,
       {"sin5"},
       "float S(cos)(float x) { float t = x * (0.15915494 - Z); return S(sin5)(0.25 - abs(t - "
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
       "return intBitsToFloat((i + 127) << 23) * p; }"},
      {"log2",
       Shape::kUnary,
       {},
       "float S(log2)(float x) { int b = floatBitsToInt(x); float e = uintBitsToFloat(uint(b & "
       "2139095040) >> 8u | 1065353216u); e = (e - 1.4960938) * 256.0; float m = "
       "intBitsToFloat(b & 8388607 | 1065353216); float p = (0.095428176 * m + 0.47779095) * m + "
       "0.19782813; float q = ((0.016618466 * m + 0.20350508) * m + 0.273829) * m + 0.04049669; "
       "e += (m - 1.0) * (p / q); return b == 2139095040 ? x : e; }"},
      {"exp",
       Shape::kUnary,
       {"exp2"},
       "float S(exp)(float x) { return S(exp2)((1.442695 - Z) * x); }"},
      {"log",
       Shape::kUnary,
       {"log2"},
       "float S(log)(float x) { return (0.6931472 - Z) * S(log2)(x); }"},
      {"pow",
       Shape::kBinary,
       {"exp2", "log2"},
       "float S(pow)(float x, float y) { return S(exp2)(S(log2)(x) * y); }"},
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
      // atan(y_over_x) and atan(y, x): the same name, told apart by arity.
      {"atan",
       Shape::kUnary,
       {"atan01"},
       "float S(atan)(float x) { float a = abs(x); bool o = !(a < 1.0); float t = "
       "S(atan01)(o ? 1.0 / a : a); float r = o ? 1.5707964 - t : t; return "
       "intBitsToFloat(floatBitsToInt(r) ^ (floatBitsToInt(x) & int(0x80000000u))); }"
       " float S(atan)(float y, float x) { bool s = y < 0.0; float theta = s ? -3.1415927 : "
       "0.0; float x0 = intBitsToFloat((floatBitsToInt(y) & int(0x80000000u)) ^ "
       "floatBitsToInt(x)); float y0 = abs(y); bool q = x0 < 0.0; theta += q ? 1.5707964 : 0.0; "
       "float x1 = q ? y0 : x0; float y1 = q ? -x0 : y0; bool o = !(y1 < x1); float x2 = o ? y1 "
       ": x1; float y2 = o ? x1 : y1; bool inf_y = isinf(y2); float t = S(atan01)(y2 / x2); "
       "theta += (x2 != 0.0 && !inf_y) ? (o ? 1.5707964 - t : t) : (inf_y ? 0.7853982 : 0.0); "
       "return (s && q && o && !inf_y) ? -t : theta; }"},
      // SwiftShader's dFdx is coarse, the top row's difference for the whole 2x2 quad
      // (v1 - v0 in every lane); llvmpipe's is per row. In the odd row, v - dFdy(v) is
      // the even row's value, exactly when the difference is. Its dFdy is already
      // the coarse one (measured). fwidth = |dFdx| + |dFdy| of those, and -0.0 where
      // both are 0 (measured in Chromium: 1.0 / fwidth(c) is -inf there).
      {"dFdx",
       Shape::kUnary,
       {},
       "float S(dFdx)(float v) { return dFdx(mod(floor(gl_FragCoord.y), 2.0) > 0.5 ? v - dFdy(v) "
       ": v); }"},
      {"fwidth",
       Shape::kUnary,
       {"dFdx"},
       "float S(fwidth)(float v) { float f = abs(S(dFdx)(v)) + abs(dFdy(v)); return f == 0.0 ? "
       "-f : f; }"},
      // SwiftShader's min and max are x86's minps/maxps: the second operand when either
      // is NaN (min(1.0, NaN) is NaN, llvmpipe gives 1.0). The comparison is xored
      // with an opaque false: Mesa turns `a < b ? a : b` back into its own fmin.
      {"min",
       Shape::kMinMax,
       {},
       "float S(min)(float a, float b) { return (a < b) != (Z < 0.0) ? a : b; }"},
      {"max",
       Shape::kMinMax,
       {},
       "float S(max)(float a, float b) { return (a > b) != (Z < 0.0) ? a : b; }"},
      {"mix",
       Shape::kMix,
       {},
       "float S(mix)(float x, float y, float a) { return a * (y - x) + x; }"},
      // dot: x0 * y0, then MulAdd(xi, yi, d) for each further component.
      {"dot",
       Shape::kReduction,
       {},
       "float S(dot)(@ x, @ y) { float d = x.x * y.x;# d = x.# * y.# + d; return d; }",
       "float S(dot)(float x, float y) { return x * y; }"},
      {"length",
       Shape::kReduction,
       {"dot"},
       "float S(length)(@ x) { return sqrt(S(dot)(x, x)); }",
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
       {"dot"},
       "@ S(normalize)(@ x) { float r = 1.0 / (sqrt(S(dot)(x, x)) - Z); return r * "
       "x; }"},
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

const Helper* Find(std::string_view name) {
  for (const Helper& helper : Helpers()) {
    if (helper.builtin == name) return &helper;
  }
  return nullptr;
}

// `S(name)` -> `shaderport_name`, `Z` -> the opaque zero.
std::string Spell(std::string_view text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == 'Z' && (i + 1 == text.size() || text[i + 1] == ')' || text[i + 1] == ' ')) {
      out.append(kOpaqueZeroUniform);
      continue;
    }
    if (text.compare(i, 2, "S(") == 0 &&
        (i == 0 ||
         (!std::isalnum(static_cast<unsigned char>(text[i - 1])) && text[i - 1] != '_'))) {
      const size_t close = text.find(')', i);
      out += "shaderport_";
      out.append(text.substr(i + 2, close - i - 2));
      i = close;
      continue;
    }
    out.push_back(text[i]);
  }
  return out;
}

constexpr std::array<std::string_view, 3> kVectors = {"vec2", "vec3", "vec4"};
constexpr std::array<char, 4> kComponents = {'x', 'y', 'z', 'w'};

// kReduction/kGeometric: `@` is the type; the part between the two `#`-free ends
// repeats: "head# body with # ...; tail" -> the body once per component after the
// first, `#` replaced by the component.
std::string ForSize(std::string_view text, std::string_view type, int size) {
  std::string typed;
  for (const char c : text) {
    if (c == '@') {
      typed.append(type);
    } else {
      typed.push_back(c);
    }
  }
  const size_t first = typed.find('#');
  if (first == std::string::npos) return typed;
  const size_t end = typed.find(';', typed.rfind('#'));
  const std::string head = typed.substr(0, first);
  const std::string body = typed.substr(first + 1, end + 1 - first - 1);
  std::string out = head;
  for (int i = 1; i < size; ++i) {
    for (const char c : body) {
      if (c == '#') {
        out.push_back(kComponents[static_cast<size_t>(i)]);
      } else {
        out.push_back(c);
      }
    }
  }
  out += typed.substr(end + 1);
  return out;
}

// Componentwise vector overloads of a float helper with `arity` float parameters;
// with `float_tail` > 0 also the overload whose last `float_tail` parameters are
// floats (mix(vec3, vec3, float), clamp(vec3, float, float)).
std::string Componentwise(std::string_view name, int arity, int float_tail) {
  std::string out;
  const std::string helper = "shaderport_" + std::string(name);
  for (size_t v = 0; v < kVectors.size(); ++v) {
    const std::string_view type = kVectors[v];
    const int size = static_cast<int>(v) + 2;
    for (int variant = 0; variant < (float_tail > 0 ? 2 : 1); ++variant) {
      const int first_float = variant == 1 ? arity - float_tail : arity;
      out += " " + std::string(type) + " " + helper + "(";
      for (int p = 0; p < arity; ++p) {
        const bool is_float = p >= first_float;
        out +=
            (p > 0 ? ", " : "") + std::string(is_float ? "float" : type) + " a" + std::to_string(p);
      }
      out += ") { return " + std::string(type) + "(";
      for (int c = 0; c < size; ++c) {
        out += (c > 0 ? ", " : "") + helper + "(";
        for (int p = 0; p < arity; ++p) {
          const bool is_float = p >= first_float;
          out += (p > 0 ? ", " : "") + ("a" + std::to_string(p)) +
                 (is_float ? "" : std::string(".") + kComponents[static_cast<size_t>(c)]);
        }
        out += ")";
      }
      out += "); }";
    }
  }
  return out;
}

// Each parameter of each function in `text` starts with `p = zero < 0.0 ? -p : p;` and
// each `return x;` becomes `return (x) - zero;`: in Chromium the helper's arithmetic
// runs inside SwiftShader, out of reach of the SPIR-V optimiser, so Mesa must not mix
// the caller's arithmetic into it either (it turns `(v * 0.61) * 78.233` into
// `v * 47.72`, `v * a + v * b` into `v * (a + b)`, `(p * x) * k` into `(p * k) * x`).
// Parameters do not use `p - zero`: Mesa turns `0.0 - zero` into `-zero`, a zero of
// the wrong sign (atan(0.0, x) flipped); a result is never a constant, since no
// constant reaches the helper. Multiplying results by a select changed 10 pictures
// of the shared corpus (measured), so they keep `- zero`. Without `parameters` only
// the results are: where every value reaches an invariant output, Mesa keeps the
// caller's arithmetic exact anyway, and the selects made a quarter of the compile.
std::string WithOpaqueParameters(std::string_view text, bool parameters) {
  constexpr std::string_view kReturn = "return ";
  const std::string opaque = std::string(kOpaqueZeroUniform) + " < 0.0 ? -";
  std::string out;
  int depth = 0;
  for (size_t i = 0; i < text.size();) {
    if (depth > 0 && text.compare(i, kReturn.size(), kReturn) == 0) {
      const size_t end = text.find(';', i);
      out += "return (";
      out.append(text.substr(i + kReturn.size(), end - i - kReturn.size()));
      out += ") - " + std::string(kOpaqueZeroUniform);
      i = end;
      continue;
    }
    if (depth == 0 && text[i] == '(') {
      const size_t close = text.find(')', i);
      const size_t brace = text.find('{', close);
      const std::string_view list = text.substr(i + 1, close - i - 1);
      out.append(text.substr(i, brace + 1 - i));
      for (size_t begin = 0; parameters && begin < list.size();) {
        size_t end = list.find(',', begin);
        if (end == std::string_view::npos) end = list.size();
        const std::string_view parameter = list.substr(begin, end - begin);
        const std::string name(parameter.substr(parameter.rfind(' ') + 1));
        out.append(" ").append(name).append(" = ").append(opaque).append(name).append(" : ");
        out.append(name).append(";");
        begin = end + 1;
      }
      i = brace + 1;
      depth = 1;
      continue;
    }
    if (text[i] == '{') ++depth;
    if (text[i] == '}') --depth;
    out.push_back(text[i++]);
  }
  return out;
}

std::string Definition(const Helper& helper, bool opaque_parameters) {
  switch (helper.shape) {
    case Shape::kInternal:
      return Spell(helper.text);
    case Shape::kFromUint: {
      std::string out = Spell(helper.text);
      for (size_t v = 0; v < kVectors.size(); ++v) {
        const std::string type(kVectors[v]);
        out.append(" ").append(type).append(" shaderport_u2f(u").append(type);
        out.append(" a) { return ").append(type).append("(");
        for (size_t c = 0; c <= v + 1; ++c) {
          out += std::string(c > 0 ? ", " : "") + "shaderport_u2f(a." + kComponents[c] + ")";
        }
        out += "); }";
      }
      return out;
    }
    case Shape::kUnary: {
      std::string out = WithOpaqueParameters(Spell(helper.text), opaque_parameters) +
                        Componentwise(helper.builtin, 1, 0);
      if (helper.builtin == "atan") out += Componentwise(helper.builtin, 2, 0);
      return out;
    }
    case Shape::kBinary:
      return WithOpaqueParameters(Spell(helper.text), opaque_parameters) +
             Componentwise(helper.builtin, 2, 0);
    case Shape::kMinMax:
      return WithOpaqueParameters(Spell(helper.text), opaque_parameters) +
             Componentwise(helper.builtin, 2, 1);
    case Shape::kMix:
      // Always opaque: without, Mesa still reshaped mix's arithmetic with the caller's
      // (4sXcWj drew 23 of 64 blocks off Chromium's; the selects of the others made no
      // difference there).
      return WithOpaqueParameters(Spell(helper.text), true) + Componentwise(helper.builtin, 3, 1);
    case Shape::kReduction:
    case Shape::kGeometric: {
      std::string out = WithOpaqueParameters(
          Spell(helper.float_text.empty() ? ForSize(helper.text, "float", 1) : helper.float_text),
          opaque_parameters);
      for (size_t v = 0; v < kVectors.size(); ++v) {
        out += " " + WithOpaqueParameters(
                         Spell(ForSize(helper.text, kVectors[v], static_cast<int>(v) + 2)),
                         opaque_parameters);
      }
      return out;
    }
  }
  return {};
}

void AddWithCalls(std::string_view name, std::vector<const Helper*>& ordered,
                  std::set<std::string_view>& seen) {
  const Helper* helper = Find(name);
  if (helper == nullptr || !seen.insert(helper->builtin).second) return;
  for (const std::string_view call : helper->calls) AddWithCalls(call, ordered, seen);
  ordered.push_back(helper);  // after what it calls
}

}  // namespace

bool HasCpuMathDefinition(std::string_view builtin) {
  const Helper* helper = Find(builtin);
  return helper != nullptr && (helper->shape != Shape::kInternal || builtin == "cross");
}

std::string CpuMathHelperName(std::string_view builtin) {
  return "shaderport_" + std::string(builtin);
}

namespace {

bool IsNumericType(std::string_view word) {
  return word == "float" || word == "int" || word == "uint" || word.starts_with("vec") ||
         word.starts_with("ivec") || word.starts_with("uvec");
}

}  // namespace

std::string MacroProofHelperText(std::string_view text) {
  // Keywords and built-ins the helpers use; everything else gets the prefix.
  constexpr std::string_view kKept =
      " float vec2 vec3 vec4 int uint uvec2 uvec3 uvec4 bool bvec2 bvec3 bvec4 return if else "
      "uniform highp true false abs sign roundEven floor sqrt min max clamp mix equal greaterThan "
      "intBitsToFloat floatBitsToInt uintBitsToFloat isinf mod dFdx dFdy gl_FragCoord ";
  auto kept = [&](std::string_view word) {
    return kKept.find(" " + std::string(word) + " ") != std::string_view::npos;
  };
  constexpr std::string_view kPrefix = "shaderport_";
  std::string out;
  for (size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (std::isdigit(c)) {  // a number with its suffix and exponent
      while (i < text.size() &&
             (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '.' ||
              ((text[i] == '-' || text[i] == '+') && (text[i - 1] == 'e' || text[i - 1] == 'E')))) {
        out.push_back(text[i++]);
      }
      continue;
    }
    if (!std::isalpha(c) && c != '_') {
      out.push_back(text[i++]);
      continue;
    }
    size_t end = i;
    while (end < text.size() &&
           (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_')) {
      ++end;
    }
    const std::string_view word = text.substr(i, end - i);
    const size_t component = std::string_view("xyzw").find(word.front());
    if (!out.empty() && out.back() == '.' && word.size() == 1 &&
        component != std::string_view::npos) {
      // A swizzle: `.z` would meet a user's `#define z ...`.
      out.back() = '[';
      out.push_back(static_cast<char>('0' + component));
      out.push_back(']');
    } else if (word.starts_with(kPrefix) || kept(word)) {
      // A declaration's type gets `highp`: a WebGL2 fragment shader's default int
      // precision is mediump, which Mesa computes in 16 bits.
      const bool declares =
          IsNumericType(word) && end < text.size() && text[end] == ' ' && end + 1 < text.size() &&
          (std::isalpha(static_cast<unsigned char>(text[end + 1])) || text[end + 1] == '_') &&
          !out.ends_with("highp ");
      if (declares) out.append("highp ");
      out.append(word);
    } else {
      out.append(kPrefix).append(word);
    }
    i = end;
  }
  return out;
}

std::string CpuMathDefinitions(const std::set<std::string>& builtins, bool declare_zero,
                               bool opaque_parameters) {
  std::vector<const Helper*> ordered;
  std::set<std::string_view> seen;
  for (const std::string& name : builtins) AddWithCalls(name, ordered, seen);
  bool zero = declare_zero;
  for (const Helper* helper : ordered) {
    zero = zero || helper->shape != Shape::kFromUint;
  }
  std::string text;
  if (zero) text = "uniform highp float " + std::string(kOpaqueZeroUniform) + "; ";
  for (const Helper* helper : ordered) text += Definition(*helper, opaque_parameters) + " ";
  return MacroProofHelperText(text);
}

}  // namespace shaderport::glsl
