// The browser-semantics transforms: exact output text for each behaviour, and every
// output must still compile in glslang with the same number of lines.
#include "glsl/webgl_semantics/browser_semantics.h"

#include <gtest/gtest.h>

#include "source/source_manager.h"
#include "webgl_semantics/apply_semantics.h"

namespace shaderport::glsl {
namespace {

using testing_support::Apply;
using testing_support::Body;

// The render probe without zero-initialisation, whose edits would crowd the texts.
BrowserSemanticsOptions ProbeOnly() {
  BrowserSemanticsOptions options;
  options.zero_initialize = false;
  options.add_render_probe = true;
  return options;
}

TEST(BrowserSemantics, ZeroInitializesLocalsOfEveryType) {
  const auto result = Apply(
      "struct S { float a; ivec2 b; };\n"
      "void main() { vec4 c; int i, j = 2; bool b; mat3 m; S s; float a[2]; uint u;\n"
      "o = c; }\n");
  EXPECT_EQ(Body(result),
            "struct S { float a; ivec2 b; };\n"
            "void main() { o = vec4(0.0); vec4 c = vec4(0.0); int i = 0, j = 2; bool b = false; "
            "mat3 m = mat3(0.0); S s = S(0.0, ivec2(0)); float a[2] = float[2](0.0, 0.0); "
            "uint u = 0u;\n"
            "o = c; }\n");
  EXPECT_EQ(result.initialized, 8U);  // the output o and seven locals
}

TEST(BrowserSemantics, ZeroInitializesGlobalsButNotUniformsOrConstants) {
  const auto result = Apply(
      "uniform float t; const float k = 1.0; vec3 g; float h[3];\n"
      "void main() { o = vec4(g, t + k + h[0]); }\n");
  EXPECT_EQ(Body(result),
            "uniform float t; const float k = 1.0; vec3 g = vec3(0.0); float h[3] = float[3](0.0, "
            "0.0, 0.0);\n"
            "void main() { o = vec4(0.0); o = vec4(g, t + k + h[0]); }\n");
}

TEST(BrowserSemantics, LongArraysAreZeroedInALoop) {
  const auto result = Apply("void main() { float a[100]; o = vec4(a[5]); }\n");
  EXPECT_EQ(Body(result),
            "void main() { o = vec4(0.0); float a[100]; for (int shaderport_i = 0; shaderport_i < "
            "100; ++shaderport_i) a[shaderport_i] = 0.0; o = vec4(a[5]); }\n");
}

TEST(BrowserSemantics, OutParametersOnlyWhenAsked) {
  const std::string body = "void f(out vec3 v, inout float w) { w += 1.0; }\nvoid main() { }\n";
  EXPECT_EQ(Body(Apply(body)),
            "void f(out vec3 v, inout float w) { w += 1.0; }\nvoid main() { o = vec4(0.0); }\n");
  BrowserSemanticsOptions options;
  options.zero_out_parameters = true;
  EXPECT_EQ(Body(Apply(body, options)),
            "void f(out vec3 v, inout float w) { v = vec3(0.0); w += 1.0; }\n"
            "void main() { o = vec4(0.0); }\n");
}

TEST(BrowserSemantics, ClampsDynamicIndicesOnly) {
  BrowserSemanticsOptions options;
  options.zero_initialize = false;
  const auto result = Apply(
      "uniform int n; uniform uint u; const int K = 1;\n"
      "void main() { vec3 c = vec3(0); float a[4] = float[4](1.,2.,3.,4.); mat2 m = mat2(1.);\n"
      "c[n] = a[n + 1]; c[K] = a[2]; c.x = m[u][n]; o = vec4(c, 1.); }\n",
      options);
  EXPECT_EQ(Body(result),
            "uniform int n; uniform uint u; const int K = 1;\n"
            "void main() { vec3 c = vec3(0); float a[4] = float[4](1.,2.,3.,4.); mat2 m = "
            "mat2(1.);\n"
            "c[clamp((n), 0, 2)] = a[clamp((n + 1), 0, 3)]; c[K] = a[2]; c.x = "
            "m[clamp(int(u), 0, 1)][clamp((n), 0, 1)]; o = vec4(c, 1.); }\n");
  EXPECT_EQ(result.clamped, 4U);
}

TEST(BrowserSemantics, MacroUsesAreWrappedWholeOrLeftAlone) {
  BrowserSemanticsOptions options;
  options.zero_initialize = false;
  const auto result = Apply(
      "#define IDX (n * 2)\n#define AT(v, i) v[i]\nuniform int n;\n"
      "void main() { vec3 c = vec3(0); c[IDX] = 1.0; o = vec4(AT(c, n)); }\n",
      options);
  EXPECT_EQ(Body(result),
            "#define IDX (n * 2)\n#define AT(v, i) v[i]\nuniform int n;\n"
            "void main() { vec3 c = vec3(0); c[clamp((IDX), 0, 2)] = 1.0; o = vec4(AT(c, n)); }\n");
  EXPECT_EQ(result.skipped, 1U);
}

TEST(BrowserSemantics, RenderProbeCountsLoopsAndMarksOutputWrites) {
  BrowserSemanticsOptions options = ProbeOnly();
  const auto result = Apply(
      "void main() { float s = 0.0; for (int i = 0; i < 9; i++) s += 1.0;\n"
      "while (s > 0.0) { s -= 2.0; } if (s < 0.0) o = vec4(s); }\n",
      options);
  EXPECT_TRUE(result.render_probe);
  EXPECT_TRUE(result.tracks_output_writes);
  EXPECT_EQ(result.counted_loops, 2U);
  EXPECT_EQ(result.texts.front(),
            "#version 300 es\nprecision highp float;\nprecision highp int;\n"
            "layout(location = 0) out vec4 o;\n"
            "layout(location = 1) out highp vec4 shaderport_probe; void main() { "
            "shaderport_probe = vec4(0.0, 0.0, 0.0, 0.0); float s = 0.0; for (int i = 0; i < 9; "
            "i++) { shaderport_probe[0] += 1.0; s += 1.0; }\n"
            "while (s > 0.0) { shaderport_probe[0] += 1.0; s -= 2.0; } "
            "if (s < 0.0) { o = vec4(s); shaderport_probe[1] = 1.0; } }\n");
}

// For a main() that sets alpha itself, the probe is a variable that the end of main()
// writes to the output's alpha, so the render needs one colour target.
TEST(BrowserSemantics, RenderProbeCanTravelInTheOutputsAlpha) {
  BrowserSemanticsOptions options = ProbeOnly();
  options.probe_in_alpha = true;
  const auto result = Apply(
      "void main() { float s = 0.0; for (int i = 0; i < 9; i++) s += 1.0;\n"
      "if (s < 0.0) o = vec4(s); }\n",
      options);
  EXPECT_TRUE(result.render_probe);
  EXPECT_TRUE(result.probe_in_alpha);
  EXPECT_EQ(result.texts.front(),
            "#version 300 es\nprecision highp float;\nprecision highp int;\nout vec4 o;\n"
            "highp vec4 shaderport_probe = vec4(0.0, 0.0, 0.0, 0.0); void main() { float s = 0.0; "
            "for (int i = 0; i < 9; i++) { shaderport_probe[0] += 1.0; s += 1.0; }\n"
            "if (s < 0.0) { o = vec4(s); shaderport_probe[1] = 1.0; } o[3] = shaderport_probe[1] "
            "!= 0.0 ? shaderport_probe[0] : -1.0 - shaderport_probe[0]; }\n");
}

// A main() whose end comes from a macro, or that may return before its end, cannot take
// the alpha write: the probe keeps its own output.
TEST(BrowserSemantics, RenderProbeKeepsItsOutputWhenMainsEndIsNotReached) {
  BrowserSemanticsOptions options = ProbeOnly();
  options.probe_in_alpha = true;
  for (const char* main : {"#define END }\nvoid main() { o = vec4(1.0); END\n",
                           "void main() { o = vec4(1.0); if (o.x > 0.5) return; o.y = 0.0; }\n"}) {
    const auto result = Apply(main, options);
    EXPECT_TRUE(result.render_probe) << main;
    EXPECT_FALSE(result.probe_in_alpha) << main;
    EXPECT_NE(result.texts.front().find("layout(location = 1) out highp vec4 shaderport_probe;"),
              std::string::npos)
        << result.texts.front();
  }
}

TEST(BrowserSemantics, RenderProbeMarksWritesOfMainImagesOutParameter) {
  BrowserSemanticsOptions options = ProbeOnly();
  const auto result = Apply(
      "void paint(out vec4 c) { c = vec4(1.0); }\n"
      "void mainImage(out vec4 f, vec2 p) { for (int i = 0; i < 2; i++) f.x += 1.0;\n"
      "if (p.x > 1.0) paint(f); }\n"
      "void main() { vec4 c = vec4(0.0); mainImage(c, gl_FragCoord.xy); o = c; }\n",
      options);
  EXPECT_TRUE(result.tracks_output_writes);
  EXPECT_NE(result.texts.front().find("for (int i = 0; i < 2; i++) { shaderport_probe[0] += 1.0; "
                                      "{ f.x += 1.0; shaderport_probe[1] = 1.0; } }"),
            std::string::npos)
      << result.texts.front();
  EXPECT_NE(result.texts.front().find("if (p.x > 1.0) { paint(f); shaderport_probe[1] = 1.0; }"),
            std::string::npos);
  // Writes of `o` in main() are not the site's output: mainImage's parameter is.
  EXPECT_NE(result.texts.front().find("mainImage(c, gl_FragCoord.xy); o = c; }"),
            std::string::npos);
}

TEST(BrowserSemantics, VertexShadersZeroTheirOutputsAndPosition) {
  SourceManager sources;
  const SourceFile& file = sources.Add(
      "t.vert", "#version 300 es\nin vec4 p; out vec2 uv;\nvoid main() { vec2 t; uv = t; }\n");
  const SourceFile* parts[] = {&file};
  BrowserSemanticsOptions options;
  options.vertex_stage = true;
  const auto result = ApplyBrowserSemantics(parts, options);
  EXPECT_EQ(result.texts.front(),
            "#version 300 es\nin vec4 p; out vec2 uv;\nvoid main() { gl_Position = vec4(0.0); uv "
            "= vec2(0.0); vec2 t = vec2(0.0); uv = t; }\n");
}

// Regression: a golfed loop whose header writes the output (`for (p = ...; ...; p *= ...)`)
// was wrapped in braces inside the for header, which does not compile.
TEST(BrowserSemantics, RenderProbeMarksOutputWritesInAForHeader) {
  BrowserSemanticsOptions options = ProbeOnly();
  const auto result = Apply(
      "void mainImage(out vec4 p, vec2 f) { for (p = vec4(f, 1, 0); f.x-- > 0.; p *= .9) "
      "p = (p + p.z) * .1; }\n"
      "void main() { vec4 c = vec4(0.0); mainImage(c, gl_FragCoord.xy); o = c; }\n",
      options);
  EXPECT_TRUE(result.tracks_output_writes);
  EXPECT_NE(result.texts.front().find("{ shaderport_probe[1] = 1.0; for (p = vec4(f, 1, 0);"),
            std::string::npos)
      << result.texts.front();
}

TEST(BrowserSemantics, SmoothstepIsRenamedInCallsAndMacroBodies) {
  BrowserSemanticsOptions options;
  options.zero_initialize = false;
  const auto result = Apply(
      "#define S(x, w) smoothstep(-w, w, x)\n"
      "void main() { float v = smoothstep(0.1, 0.1, gl_FragCoord.x) + S(gl_FragCoord.y, 0.0);\n"
      "o = vec4(smoothstep(vec3(0.2), vec3(0.2), vec3(v)), S(v, 0.0)); }\n",
      options);
  EXPECT_EQ(result.smoothsteps, 3U);  // two calls and the macro body's one token
  const std::string& text = result.texts.front();
  EXPECT_NE(text.find("#define S(x, w) shaderport_smoothstep(-w, w, x)\n"), std::string::npos);
  EXPECT_NE(text.find("float v = shaderport_smoothstep(0.1, 0.1, gl_FragCoord.x)"),
            std::string::npos);
  EXPECT_NE(text.find("o = vec4(shaderport_smoothstep(vec3(0.2)"), std::string::npos);
  EXPECT_NE(
      text.find("highp float shaderport_smoothstep(highp float shaderport_a, highp float "
                "shaderport_b, highp float shaderport_x) { highp float shaderport_t = "
                "clamp((shaderport_x - shaderport_a) / (shaderport_b - shaderport_a), 0.0, 1.0); "
                "return mix(shaderport_t * shaderport_t * (3.0 - 2.0 * shaderport_t), "
                "mix(float(shaderport_x > shaderport_a), float(shaderport_x < shaderport_a), "
                "floatBitsToInt(shaderport_b - shaderport_a) < 0), shaderport_a == "
                "shaderport_b); }"),
      std::string::npos);
}

TEST(BrowserSemantics, SmoothstepInAConstantInitializerStaysTheBuiltIn) {
  BrowserSemanticsOptions options;
  options.zero_initialize = false;
  const auto result = Apply(
      "const float k = smoothstep(0.0, 1.0, 0.5);\n"
      "void main() { o = vec4(smoothstep(0.0, 1.0, k)); }\n",
      options);
  EXPECT_EQ(result.smoothsteps, 0U);
  EXPECT_EQ(result.texts.front().find("shaderport_smoothstep"), std::string::npos);
}

TEST(BrowserSemantics, MediumAndLowPrecisionBecomeHigh) {
  BrowserSemanticsOptions options;
  options.zero_initialize = false;
  const auto result = Apply(
      "precision mediump int;\n#define P lowp\n"
      "void main() { mediump float t = 1000.0; P vec2 v = vec2(t); o = vec4(v, 0.0, 1.0); }\n",
      options);
  EXPECT_EQ(result.promoted, 3U);
  EXPECT_EQ(Body(result),
            "precision highp int;\n#define P highp\n"
            "void main() { highp float t = 1000.0; P vec2 v = vec2(t); o = vec4(v, 0.0, 1.0); }\n");
}

TEST(BrowserSemantics, SkippedGroupsKeepOnlyTheirConditionalDirectives) {
  BrowserSemanticsOptions options;
  options.zero_initialize = false;
  const auto result = Apply(
      "#if 0\nthis is not GLSL\n#elseif 1\n  #if 1\n#endif\n#else\nvoid main() { o = vec4(1); }\n"
      "#endif\n",
      options);
  EXPECT_EQ(Body(result),
            "#if 0\n\n\n  #if 1\n#endif\n#else\nvoid main() { o = vec4(1); }\n#endif\n");
}

TEST(BrowserSemantics, FunctionsThatRunOffTheirEndReturnZero) {
  BrowserSemanticsOptions options;
  options.clamp_indices = false;
  const auto result = Apply(
      "struct S { float a; };\n"
      "float f(int i) { if (i == 0) return 0.5; }\nS g() { return S(1.0); }\nvoid h() {}\n"
      "void main() { o = vec4(f(1), g().a, 0.0, 1.0); h(); }\n",
      options);
  EXPECT_EQ(result.default_returns, 2U);
  EXPECT_EQ(Body(result),
            "struct S { float a; };\n"
            "float f(int i) { if (i == 0) return 0.5;  return 0.0; }\n"
            "S g() { return S(1.0);  return S(0.0); }\nvoid h() {}\n"
            "void main() { o = vec4(0.0); o = vec4(f(1), g().a, 0.0, 1.0); h(); }\n");
}

TEST(BrowserSemantics, FragmentShadersWithoutAnIntPrecisionGetHighp) {
  // The default is mediump, which Mesa computes in 16 bits (browsers in 32).
  SourceManager sources;
  const SourceFile& file = sources.Add(
      "t.frag",
      "#version 300 es\nprecision highp float;\nout vec4 o;\nvoid main() { o = vec4(1); }\n");
  const SourceFile* parts[] = {&file};
  BrowserSemanticsOptions options;
  options.zero_initialize = false;
  const auto result = ApplyBrowserSemantics(parts, options);
  EXPECT_EQ(
      result.texts.front(),
      "#version 300 es\nprecision highp int; precision highp float;\nout vec4 o;\nvoid main() "
      "{ o = vec4(1); }\n");
}

TEST(BrowserSemantics, BrokenCodeIsLeftAsItIs) {
  SourceManager sources;
  const SourceFile& file = sources.Add("t.frag", "#version 300 es\nvoid main() { vec4 c; +; }\n");
  const SourceFile* parts[] = {&file};
  const auto result = ApplyBrowserSemantics(parts, {});
  EXPECT_FALSE(result.applied);
  EXPECT_EQ(result.texts.front(), file.Text());
}

TEST(BrowserSemantics, PartsAreEditedSeparately) {
  SourceManager sources;
  const SourceFile& header =
      sources.Add("h", "#version 300 es\nprecision highp float;\nout vec4 o;\nvec3 g;\n");
  const SourceFile& user = sources.Add("u", "void main() { float x; o = vec4(g, x); }\n");
  const SourceFile* parts[] = {&header, &user};
  const auto result = ApplyBrowserSemantics(parts, {});
  EXPECT_EQ(result.texts[0],
            "#version 300 es\nprecision highp int; precision highp float;\nout vec4 o;\nvec3 g = "
            "vec3(0.0);\n");
  EXPECT_EQ(result.texts[1], "void main() { o = vec4(0.0); float x = 0.0; o = vec4(g, x); }\n");
}

}  // namespace
TEST(BrowserSemantics, SourceOrderArithmeticMakesOutputsAndConditionsInvariant) {
  BrowserSemanticsOptions options = ProbeOnly();
  options.source_order_arithmetic = true;
  const auto result = Apply(
      "void main() { float s = 0.0; for (int i = 0; i < 9 && s < 4.0; i++) s += 1.5;\n"
      "do { s -= 2.0; } while (s > 0.0); if (s < 0.0) o = vec4(s); }\n",
      options);
  EXPECT_EQ(result.invariant_outputs, 1U);
  EXPECT_EQ(result.exposed_conditions, 3U);
  EXPECT_EQ(result.texts.front(),
            "#version 300 es\nprecision highp float;\nprecision highp int;\n"
            "invariant layout(location = 0) out vec4 o;\n"
            "invariant layout(location = 1) out highp vec4 shaderport_probe; void main() { "
            "shaderport_probe = vec4(0.0, 0.0, 0.0, 0.0); float s = 0.0; for (int i = 0; "
            "((shaderport_probe[2] = float(i < 9 && s < 4.0)) != 0.0); i++) { "
            "shaderport_probe[0] += 1.0; s += 1.5; }\n"
            "do { shaderport_probe[0] += 1.0; s -= 2.0; } while "
            "(((shaderport_probe[2] = float(s > 0.0)) != 0.0)); if (((shaderport_probe[2] = "
            "float(s < 0.0)) != 0.0)) { o = vec4(s); shaderport_probe[1] = 1.0; } }\n");
}

TEST(BrowserSemantics, SourceOrderArithmeticWithoutTheProbeOnlyMakesOutputsInvariant) {
  BrowserSemanticsOptions options;
  options.zero_initialize = false;
  options.source_order_arithmetic = true;
  const auto result = Apply("void main() { if (o.x > 0.0) o = vec4(1.0); }\n", options);
  EXPECT_EQ(result.invariant_outputs, 1U);
  EXPECT_EQ(result.exposed_conditions, 0U);
  EXPECT_EQ(result.texts.front(),
            "#version 300 es\nprecision highp float;\nprecision highp int;\n"
            "invariant out vec4 o;\n"
            "void main() { if (o.x > 0.0) o = vec4(1.0); }\n");
}

// Golfed code defines one-letter macros (`#define z Z`, `#define x ...`): the probe's
// writes must not spell a component name that such a macro would replace.
TEST(BrowserSemantics, ProbeWritesSurviveMacrosNamedLikeComponents) {
  BrowserSemanticsOptions options = ProbeOnly();
  options.source_order_arithmetic = true;
  const auto result = Apply(
      "#define x 2.0\n#define y 3.0\n#define z broken(\n"
      "void main() { float s = 0.0; for (int i = 0; i < 9; i++) s += x;\n"
      "if (s > y) o = vec4(s); }\n",
      options);
  ASSERT_TRUE(result.render_probe);
  EXPECT_EQ(result.exposed_conditions, 2U);
  EXPECT_EQ(result.texts.front().find("shaderport_probe."), std::string::npos);
}

}  // namespace shaderport::glsl
