// Math as Chromium computes it without a GPU: which calls and divisions are
// rewritten, which are left to the browser's constant folding, and that every
// output compiles with its helpers (the bits themselves are checked against
// Chromium by tests/render-parity/math and BrowserParity.MathHasChromiumsBits).
#include <gtest/gtest.h>

#include "glsl/webgl_semantics/cpu_math_library.h"
#include "webgl_semantics/apply_semantics.h"

namespace shaderport::glsl {
namespace {

using testing_support::Apply;
using testing_support::Body;

BrowserSemanticsOptions MathOnly() {
  BrowserSemanticsOptions options;
  options.zero_initialize = false;
  options.clamp_indices = false;
  options.gpu_smoothstep_edges = false;
  options.promote_precision = false;
  options.cpu_browser_math = true;
  return options;
}

bool Contains(const std::string& text, std::string_view part) {
  return text.find(part) != std::string::npos;
}

TEST(CpuBrowserMath, BuiltinCallsBecomeHelpersOfTheOverloadsCalled) {
  const auto result = Apply(
      "void main() { vec3 p = gl_FragCoord.xyz; float a = sin(p.x) + pow(p.y, 2.2) + "
      "atan(p.y, p.x) + atan(p.z) + dot(p, p) + length(p.xy);\n"
      "o = vec4(mix(p, cos(p), 0.5), exp(a) + log2(a)); }\n",
      MathOnly());
  EXPECT_EQ(result.math_calls, 10U);
  const std::string body = Body(result);
  EXPECT_TRUE(Contains(body,
                       "float a = shaderport_sin(p.x) + shaderport_pow(p.y, 2.2) + "
                       "shaderport_atan(p.y, p.x) + shaderport_atan(p.z) + "
                       "shaderport_dot(p, p) + shaderport_length(p.xy);\n"))
      << body;
  EXPECT_TRUE(Contains(body,
                       "o = vec4(shaderport_mix(p, shaderport_cos(p), 0.5), "
                       "shaderport_exp(a) + shaderport_log2(a)); }"));
  EXPECT_TRUE(Contains(body, "uniform highp float shaderport_zero;"));
  EXPECT_TRUE(Contains(body,
                       "highp vec3 shaderport_mix(highp vec3 shaderport_x, highp vec3 "
                       "shaderport_y, highp float shaderport_a)"));
  // Parameters and results pass a select on the opaque zero, so that Mesa cannot mix
  // the caller's arithmetic into the helper's (and a constant 0.0 keeps its sign).
  EXPECT_TRUE(Contains(
      body,
      "highp float shaderport_dot(highp vec3 shaderport_x, highp vec3 "
      "shaderport_y) { shaderport_x = mix(shaderport_x, -shaderport_x, "
      "bvec3(shaderport_zero < 0.0)); shaderport_y = mix(shaderport_y, "
      "-shaderport_y, bvec3(shaderport_zero < 0.0)); highp float shaderport_d = shaderport_x.x * "
      "shaderport_y.x; shaderport_d = shaderport_x.y * shaderport_y.y + "
      "shaderport_d; shaderport_d = shaderport_x.z * shaderport_y.z + "
      "shaderport_d; return (shaderport_d) - shaderport_zero; }"))
      << body;
  // Only the overloads called, and what they call: Mesa compiles every function given.
  EXPECT_TRUE(Contains(body, "highp float shaderport_sin(highp float shaderport_x)"));
  // cos(vec3) computes on the whole vector (its float overload is not needed).
  EXPECT_TRUE(Contains(body, "highp vec3 shaderport_cos(highp vec3 shaderport_x)"));
  EXPECT_TRUE(Contains(body, "highp vec3 shaderport_sin5(highp vec3 shaderport_x)"));
  for (const std::string_view unused :
       {"highp vec2 shaderport_sin(", "highp vec4 shaderport_cos(", "highp float shaderport_cos(",
        "shaderport_dot(highp vec2", "shaderport_length(highp vec3",
        "highp vec2 shaderport_exp2("}) {
    EXPECT_FALSE(Contains(body, unused)) << unused;
  }
}

TEST(CpuBrowserMath, HelperSwizzlesAvoidLettersTheShaderDefines) {
  const std::string call = "void main() { o = vec4(length(gl_FragCoord.xy)); }\n";
  const std::string plain = Body(Apply(call, MathOnly()));
  EXPECT_TRUE(Contains(plain, "shaderport_x.x * shaderport_x.x")) << plain;
  // `.x` would expand a user's `x`; `.r` is the same component.
  const std::string x = Body(Apply("#define x 1.0\n" + call, MathOnly()));
  EXPECT_TRUE(Contains(x, "shaderport_x.r * shaderport_x.r")) << x;
  // A directive line continued with a backslash and CRLF, and a define at the very end.
  const std::string continued = Body(Apply("#  define \\\r\nx 1.0\n" + call, MathOnly()));
  EXPECT_TRUE(Contains(continued, "shaderport_x.r * shaderport_x.r")) << continued;
  const std::string at_end = Body(Apply(call + "#define x", MathOnly()));
  EXPECT_TRUE(Contains(at_end, "shaderport_x.r * shaderport_x.r")) << at_end;
  const std::string all =
      Body(Apply("#define x 1.0\n#  define g(a) a\n#define q 2\n" + call, MathOnly()));
  EXPECT_TRUE(Contains(all, "shaderport_x[0] * shaderport_x[0]")) << all;
}

// Where every value reaches an invariant output (the render's main pass), Mesa keeps
// the caller's arithmetic exact, so only results pass the opaque zero; text for the
// SPIR-V optimiser, which ignores invariance, keeps the parameters' selects too.
TEST(CpuBrowserMath, InvariantOutputsLeaveParametersPlain) {
  BrowserSemanticsOptions options = MathOnly();
  options.source_order_arithmetic = true;
  options.add_render_probe = true;
  const std::string plain =
      Body(Apply("void main() { o = vec4(dot(gl_FragCoord.xy, gl_FragCoord.yx)); }\n", options));
  EXPECT_TRUE(Contains(plain,
                       "highp float shaderport_dot(highp vec2 shaderport_x, highp vec2 "
                       "shaderport_y) { highp float shaderport_d = shaderport_x.x * "
                       "shaderport_y.x; shaderport_d = shaderport_x.y * shaderport_y.y + "
                       "shaderport_d; return (shaderport_d) - shaderport_zero; }"))
      << plain;
  // mix keeps them: Mesa reshaped its arithmetic with the caller's (4sXcWj).
  const std::string mixed =
      Body(Apply("void main() { o = vec4(mix(gl_FragCoord.x, gl_FragCoord.y, 0.3)); }\n", options));
  EXPECT_TRUE(
      Contains(mixed, "shaderport_a = mix(shaderport_a, -shaderport_a, shaderport_zero < 0.0);"))
      << mixed;
  options.opaque_helper_arguments = true;
  const std::string opaque =
      Body(Apply("void main() { o = vec4(dot(gl_FragCoord.xy, gl_FragCoord.yx)); }\n", options));
  EXPECT_TRUE(Contains(
      opaque, "{ shaderport_x = mix(shaderport_x, -shaderport_x, bvec2(shaderport_zero < 0.0));"))
      << opaque;
  options.opaque_helper_arguments = false;
  options.add_render_probe = false;  // a buffer pass: its branches reach no output
  EXPECT_TRUE(Contains(
      Body(Apply("void main() { o = vec4(dot(gl_FragCoord.xy, gl_FragCoord.yx)); }\n", options)),
      "{ shaderport_x = mix(shaderport_x, -shaderport_x, bvec2(shaderport_zero < 0.0));"));
}

TEST(CpuBrowserMath, ConstantCallsAndGlobalInitializersKeepTheBuiltIn) {
  const auto result = Apply(
      "const float k = sin(0.5);\n"
      "void main() { const float c = cos(k); float v = sin(1.0) + c; o = vec4(v); }\n",
      MathOnly());
  EXPECT_EQ(result.math_calls, 0U);
  EXPECT_FALSE(Contains(result.texts.front(), "shaderport_"));
}

TEST(CpuBrowserMath, ValuesTheDriverPropagatesAsConstantsKeepTheBuiltIn) {
  // a and k reach the driver as constants (never written; every call passes one);
  // b is written, and r gets a varying argument.
  const auto result = Apply(
      "float h(float k) { return sin(k); }\n"
      "float r(float k) { return cos(k); }\n"
      "void main() { float a = 0.3; float b = 0.5; b += gl_FragCoord.x;\n"
      "o = vec4(sin(a), sin(b), h(2.0) + h(a), r(gl_FragCoord.y) + r(1.0) + gl_FragCoord.x / a); "
      "}\n",
      MathOnly());
  const std::string body = Body(result);
  EXPECT_TRUE(Contains(body, "float h(float k) { return sin(k); }\n")) << body;
  EXPECT_TRUE(Contains(body, "float r(float k) { return shaderport_cos(k); }\n")) << body;
  EXPECT_TRUE(Contains(body,
                       "o = vec4(sin(a), shaderport_sin(b), h(2.0) + h(a), "
                       "r(gl_FragCoord.y) + r(1.0) + gl_FragCoord.x * (1.0 / (a))); }\n"));
}

TEST(CpuBrowserMath, BuiltinsTheOptimiserCannotFoldKeepValuesRunTime) {
  // f's parameter is 45.0 at every call: the optimiser folds tan of a constant but not
  // radians, so tan(radians(fov)) is computed at run time (with SwiftShader's tan),
  // unlike tan(radians(45.0)), which ANGLE folds whole.
  const auto result = Apply(
      "float f(float fov) { return tan(radians(fov)) + tan(fov) + sin(abs(fov)); }\n"
      "void main() { o = vec4(f(45.0), tan(radians(45.0)), 0.0, 1.0); }\n",
      MathOnly());
  const std::string body = Body(result);
  EXPECT_TRUE(Contains(body,
                       "float f(float fov) { return shaderport_tan(radians(fov)) + tan(fov) + "
                       "shaderport_sin(abs(fov)); }"))
      << body;
  EXPECT_TRUE(Contains(body, "o = vec4(f(45.0), tan(radians(45.0)), 0.0, 1.0); }")) << body;
}

TEST(CpuBrowserMath, BooleanMixIsASelectionAndStays) {
  const auto result = Apply(
      "void main() { vec2 p = gl_FragCoord.xy; o = vec4(mix(p, -p, lessThan(p, vec2(3.0))), "
      "mix(p.x, p.y, 0.25), 1.0); }\n",
      MathOnly());
  EXPECT_EQ(result.math_calls, 1U);
  EXPECT_TRUE(Contains(Body(result),
                       "vec4(mix(p, -p, lessThan(p, vec2(3.0))), "
                       "shaderport_mix(p.x, p.y, 0.25), 1.0)"));
}

TEST(CpuBrowserMath, DivisionByAConstantMultipliesByItsReciprocal) {
  const auto result = Apply(
      "const float K = 3.3;\n"
      "void main() { vec2 p = gl_FragCoord.xy / 3.3; p /= K; float q = p.x;\n"
      "o = vec4(vec2(p.x, q * 0.3) / vec2(1.7, K), 1.0 / 2.0, 0.0); }\n",
      MathOnly());
  EXPECT_EQ(result.divisions, 3U);
  EXPECT_EQ(result.opaque_divisors, 0U);  // 1.0 / 2.0 is folded whole by both compilers
  // Through a vector constructor the reciprocal passes the opaque zero: Mesa would
  // merge it into the constants inside the constructor, the browser does not.
  EXPECT_EQ(Body(result),
            "const float K = 3.3;\n"
            "uniform highp float shaderport_zero; void main() { vec2 p = gl_FragCoord.xy * (1.0 / "
            "(3.3)); p *= (1.0 / (K)); float q = p.x;\n"
            "o = vec4(vec2(p.x, q * 0.3) * ((1.0 / (vec2(1.7, K))) - shaderport_zero), 1.0 / 2.0, "
            "0.0); }\n");
}

TEST(CpuBrowserMath, OtherDivisorsAreHiddenFromTheDriversFolding) {
  // Mesa propagates g = 0.0 out of Init() and turns `x / 0.0` into NaN or garbage;
  // the select on the opaque zero keeps every divisor exact and its sign of zero.
  // A matrix divisor and a literal zero are hidden too; integer divisions stay. Float
  // and vector divisors are selected by mix (Mesa compiles `?:` as a branch).
  const auto result = Apply(
      "float g; void Init() { g = 0.0; }\n"
      "void main() { Init(); float x = gl_FragCoord.x; int i = int(x) / 3;\n"
      "mat2 m = mat2(x) / mat2(1.5); x /= g; o = vec4(x / 0.0, m[0].x, float(i), 1.0 / g); }\n",
      MathOnly());
  EXPECT_EQ(result.divisions, 0U);
  EXPECT_EQ(result.opaque_divisors, 4U);
  EXPECT_EQ(Body(result),
            "float g; uniform highp float shaderport_zero; void Init() { g = 0.0; }\n"
            "void main() { Init(); float x = gl_FragCoord.x; int i = int(x) / 3;\n"
            "mat2 m = mat2(x) / (shaderport_zero < 0.0 ? mat2(1.0) : (mat2(1.5))); x /= "
            "mix((g), float(1.0), shaderport_zero < 0.0); o = vec4(x / mix((0.0), float(1.0), "
            "shaderport_zero < 0.0), m[0].x, float(i), 1.0 / mix((g), float(1.0), shaderport_zero "
            "< 0.0)); }\n");
}

TEST(CpuBrowserMath, NestedDivisionsCloseInnermostFirst) {
  // The inner division ends where the outer divisor ends: its closing text goes first.
  const auto result = Apply(
      "float g; void Init() { g = 0.0; }\n"
      "void main() { Init(); float x = gl_FragCoord.x; x /= gl_FragCoord.y / 2.0;\n"
      "x /= gl_FragCoord.y / g; o = vec4(x); }\n",
      MathOnly());
  const std::string body = Body(result);
  EXPECT_TRUE(Contains(body,
                       "x /= mix((gl_FragCoord.y * (1.0 / (2.0))), float(1.0), shaderport_zero < "
                       "0.0);"))
      << body;
  EXPECT_TRUE(Contains(body,
                       "x /= mix((gl_FragCoord.y / mix((g), float(1.0), shaderport_zero < 0.0)), "
                       "float(1.0), shaderport_zero < 0.0);"))
      << body;
}

TEST(CpuBrowserMath, UintToFloatConversionsRoundTwice) {
  const auto result = Apply(
      "void main() { uvec3 h = uvec3(gl_FragCoord.xyz) * 1664525u; uint k = 7u;\n"
      "o = vec4(vec3(h) / 4294967295.0, float(h.x ^ h.y) + float(k) + float(3u)); }\n",
      MathOnly());
  EXPECT_EQ(result.conversions, 2U);  // k and 3u reach the driver as constants
  EXPECT_TRUE(Contains(Body(result),
                       "o = vec4(vec3(shaderport_u2f(h)) * ((1.0 / (4294967295.0)) - "
                       "shaderport_zero), "
                       "float(shaderport_u2f(h.x ^ h.y)) + float(k) + float(3u)); }"))
      << Body(result);
}

TEST(CpuBrowserMath, DivisionsSpelledInMacroBodies) {
  // H's divisor is written in its body: rewritten there. G divides by an argument,
  // which is a constant in one use only, and F's division is folded whole in one
  // use (the browser divides exactly there): both left alone.
  const auto result = Apply(
      "#define H(k) (k * k / 7.0)\n#define G(a, b) (a / b)\n#define F(k) (k / 7.0)\n"
      "void main() { float v = gl_FragCoord.x; o = vec4(H(v), G(v, 3.0), G(v, v), F(v) + "
      "F(2.0)); }\n",
      MathOnly());
  EXPECT_EQ(result.divisions, 1U);
  EXPECT_TRUE(Contains(result.texts.front(),
                       "#define H(k) (k * k * (1.0 / (7.0)))\n"
                       "#define G(a, b) (a / b)\n"
                       "#define F(k) (k / 7.0)\n"));
}

TEST(CpuBrowserMath, ClampOfAConstantIsAnsweredFromOneBound) {
  // clamp(0.02, 2.0, h) with h < 2: the browser's optimiser gives 2.0 (x <= lo);
  // min(max(x, lo), hi) would give h.
  const auto result = Apply(
      "void main() { float h = gl_FragCoord.x; const float k = 0.3; o = vec4(clamp(0.02, 2.0, "
      "h), clamp(k, h, -1.0), clamp(h, 0.0, 1.0), clamp(0.5, 0.0, h)); }\n",
      MathOnly());
  EXPECT_EQ(result.folded_clamps, 2U);
  EXPECT_TRUE(Contains(Body(result),
                       "o = vec4(shaderport_clamp_lo(0.02, 2.0, h), shaderport_clamp_hi(k, h, "
                       "-1.0), clamp(h, 0.0, 1.0), clamp(0.5, 0.0, h)); }"))
      << Body(result);
}

TEST(CpuBrowserMath, FoldedClampKeepsTheEditsInsideItsArguments) {
  // The division in the unused bound is rewritten as well; cutting that bound's text
  // away would overlap its edit, and every edit of the part would be lost.
  const auto result = Apply(
      "void main() { float h = gl_FragCoord.x; float l = clamp(0.0, 1.0, (h - 1.0) / 0.5);\n"
      "o = vec4(l, sin(h), 0.0, 1.0); }\n",
      MathOnly());
  EXPECT_EQ(result.folded_clamps, 1U);
  EXPECT_EQ(result.divisions, 1U);
  EXPECT_TRUE(
      Contains(Body(result), "float l = shaderport_clamp_lo(0.0, 1.0, (h - 1.0) * (1.0 / (0.5)));"))
      << Body(result);
  EXPECT_TRUE(Contains(Body(result), "shaderport_sin(h)")) << Body(result);
}

TEST(CpuBrowserMath, MacroBodiesAreRenamedOnlyWhenEveryUseMayBe) {
  const auto result = Apply(
      "#define R(a) mat2(cos(a), sin(a), -sin(a), cos(a))\n"
      "#define H(x) fract(sin(x) * 43758.5)\n"
      "void main() { vec2 p = R(gl_FragCoord.x) * gl_FragCoord.xy; float h = H(p.x) + H(1.0);\n"
      "o = vec4(p, h, 1.0); }\n",
      MathOnly());
  const std::string& text = result.texts.front();
  EXPECT_TRUE(Contains(text,
                       "#define R(a) mat2(shaderport_cos(a), shaderport_sin(a), "
                       "-shaderport_sin(a), shaderport_cos(a))\n"));
  EXPECT_TRUE(Contains(text, "#define H(x) fract(sin(x) * 43758.5)\n"));  // H(1.0) folds
  EXPECT_EQ(result.math_calls, 4U);
}

TEST(CpuBrowserMath, HelpersAreImmuneToTheUsersMacros) {
  // Helpers are inserted after these definitions: a parameter `a` or a swizzle `.z`
  // in them would be replaced.
  BrowserSemanticsOptions options = MathOnly();
  options.gpu_smoothstep_edges = true;
  const auto result = Apply(
      "#define a 1.0\n#define z w\n#define t +\n#define d (\n#define e )\n"
      "void main() { vec3 p = gl_FragCoord.xyz; o = vec4(normalize(p) * length(p) + "
      "smoothstep(0.0, p.y, p.x) + atan(p.x, p.y), 1.0); }\n",
      options);
  EXPECT_EQ(result.math_calls, 3U);
  EXPECT_EQ(result.smoothsteps, 1U);
}

TEST(CpuBrowserMath, OffByDefaultAndForGlslEs100) {
  BrowserSemanticsOptions options = MathOnly();
  options.cpu_browser_math = false;
  const auto off = Apply("void main() { o = vec4(sin(gl_FragCoord.x) / 3.0); }\n", options);
  EXPECT_FALSE(Contains(off.texts.front(), "shaderport_"));

  SourceManager sources;
  const SourceFile& file = sources.Add(
      "t.frag",
      "precision highp float;\nvoid main() { gl_FragColor = vec4(sin(gl_FragCoord.x)); }\n");
  const SourceFile* parts[] = {&file};
  const auto es100 = ApplyBrowserSemantics(parts, MathOnly());
  EXPECT_EQ(es100.texts.front(), file.Text());
}

TEST(CpuBrowserMath, DerivativesAreCoarseAsInChromium) {
  // dFdx takes the quad's first row (the odd row reads it through dFdy), dFdy its first
  // column (the odd column reads it through dFdx): llvmpipe's are per row and column.
  const auto result = Apply(
      "void main() { float v = gl_FragCoord.x * gl_FragCoord.y;\n"
      "o = vec4(dFdx(v), dFdy(v), fwidth(vec2(v)).x, 1.0); }\n",
      MathOnly());
  EXPECT_EQ(result.math_calls, 3U);
  const std::string body = Body(result);
  EXPECT_TRUE(Contains(body,
                       "o = vec4(shaderport_dFdx(v), shaderport_dFdy(v), "
                       "shaderport_fwidth(vec2(v)).x, 1.0); }"))
      << body;
  EXPECT_TRUE(Contains(body,
                       "return (dFdy(mod(floor(gl_FragCoord.x), 2.0) > 0.5 ? shaderport_v - "
                       "dFdx(shaderport_v) : shaderport_v)) - shaderport_zero; }"))
      << body;
  EXPECT_TRUE(Contains(body,
                       "return (dFdx(mod(floor(gl_FragCoord.y), 2.0) > 0.5 ? shaderport_v - "
                       "dFdy(shaderport_v) : shaderport_v)) - shaderport_zero; }"))
      << body;
}

TEST(CpuBrowserMath, MinAndMaxGiveTheSecondOperandForNaN) {
  // SwiftShader's minps/maxps order; integer min stays the built-in.
  const auto result = Apply(
      "void main() { float v = gl_FragCoord.x; int i = min(int(v), 3);\n"
      "o = vec4(min(v, 1.0), max(vec2(v), 0.5).x, float(i), 1.0); }\n",
      MathOnly());
  EXPECT_EQ(result.math_calls, 2U);
  const std::string body = Body(result);
  EXPECT_TRUE(Contains(body,
                       "int i = min(int(v), 3);\no = vec4(shaderport_min(v, 1.0), "
                       "shaderport_max(vec2(v), 0.5).x, float(i), 1.0); }"))
      << body;
  // A select by mix (Mesa compiles `?:` as a branch first); vectors at once.
  EXPECT_TRUE(Contains(body,
                       "return (mix(shaderport_b, shaderport_a, (shaderport_a < shaderport_b) "
                       "!= (shaderport_zero < 0.0))) - shaderport_zero; }"))
      << body;
  EXPECT_TRUE(Contains(body,
                       "highp vec2 shaderport_max(highp vec2 shaderport_a0, highp float "
                       "shaderport_a1) {"))
      << body;
  EXPECT_TRUE(Contains(body,
                       "highp vec2 shaderport_b = vec2(shaderport_a1); return "
                       "(mix(shaderport_b, shaderport_a0, notEqual(greaterThan(shaderport_a0, "
                       "shaderport_b), bvec2(shaderport_zero < 0.0)))) - shaderport_zero; }"))
      << body;
}

TEST(CpuBrowserMath, LibraryDefinesWhatItsHelpersCall) {
  const std::string text = CpuMathDefinitions({"tan", "pow", "reflect"}, false, true);
  for (const std::string_view helper :
       {"shaderport_sin5(", "shaderport_sin(", "shaderport_cos(", "shaderport_exp2(",
        "shaderport_log2(", "shaderport_dot(", "uniform highp float shaderport_zero;"}) {
    EXPECT_TRUE(Contains(text, helper)) << helper;
  }
  // Each helper is defined after the ones it calls.
  EXPECT_LT(text.find("float shaderport_sin5("), text.find("float shaderport_sin("));
  EXPECT_LT(text.find("float shaderport_exp2("), text.find("float shaderport_pow("));
  EXPECT_EQ(text.find('\n'), std::string::npos);
}

TEST(CpuBrowserMath, LibraryDefinesOneOverloadWithWhatItCalls) {
  const std::string text =
      CpuMathDefinitions({"pow(vec3,vec3)", "reflect(vec2,vec2)", "atan(vec2,vec2)"}, false, false);
  // pow(vec3) on whole vectors calls exp2 and log2 of vec3; atan(vec2) calls atan of
  // floats per component; reflect calls dot of its own type.
  for (const std::string_view wanted :
       {"highp vec3 shaderport_pow(highp vec3", "highp vec3 shaderport_exp2(highp vec3",
        "highp vec3 shaderport_log2(highp vec3", "highp vec2 shaderport_reflect(highp vec2",
        "highp float shaderport_dot(highp vec2", "highp vec2 shaderport_atan(highp vec2",
        "highp float shaderport_atan(highp float shaderport_y", "highp float shaderport_atan01("}) {
    EXPECT_TRUE(Contains(text, wanted)) << wanted;
  }
  for (const std::string_view unused :
       {"highp vec2 shaderport_pow(", "highp float shaderport_pow(", "highp float shaderport_exp2(",
        "highp float shaderport_dot(highp vec3", "highp vec3 shaderport_reflect(",
        "highp vec3 shaderport_atan("}) {
    EXPECT_FALSE(Contains(text, unused)) << unused;
  }
  // A signature no helper has stands for all overloads.
  EXPECT_TRUE(
      Contains(CpuMathDefinitions({"sin(int)"}, false, false), "highp vec4 shaderport_sin("));
}

}  // namespace
}  // namespace shaderport::glsl
