#include "validate/shadertoy_contract.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "validate/validate_test_util.h"

namespace shaderport::validate {
namespace {

using testing::Where;

constexpr model::ChannelKinds kAll2D = {model::ChannelKind::k2D, model::ChannelKind::k2D,
                                        model::ChannelKind::k2D, model::ChannelKind::k2D};

struct Compiled {
  SourceManager sources;
  FileId common = kNoFile;
  FileId pass = kNoFile;
  ValidationResult result;
};

std::unique_ptr<Compiled> CompilePass(const std::string& code,
                                      model::PassKind type = model::PassKind::kImage,
                                      const std::string& common = "",
                                      const model::ChannelKinds& channels = kAll2D) {
  auto out = std::make_unique<Compiled>();
  const SourceFile* common_file = nullptr;
  if (!common.empty()) {
    common_file = &out->sources.Add("Common", common);
    out->common = common_file->Id();
  }
  const SourceFile& pass = out->sources.Add("Image", code);
  out->pass = pass.Id();
  out->result =
      ValidateWithGlslang(ComposeShaderToyRequest(out->sources, type, channels, common_file, pass));
  return out;
}

std::string Rules(const DiagnosticList& diagnostics) {
  std::string out;
  for (const auto& d : diagnostics) out += d.rule_id + " " + d.message + "\n";
  return out;
}

TEST(ShaderToyContractTest, HeaderDeclaresTheSiteUniformsAndSamplers) {
  const std::string header =
      ShaderToyHeader(model::PassKind::kImage, {model::ChannelKind::k2D, model::ChannelKind::kCube,
                                                model::ChannelKind::k3D, model::ChannelKind::k2D});
  EXPECT_TRUE(header.starts_with("#version 300 es\n#ifdef GL_ES\nprecision highp float;\n"));
  for (const char* line :
       {"uniform vec3 iResolution;", "uniform float iTime;", "uniform float iChannelTime[4];",
        "uniform vec4 iMouse;", "uniform vec4 iDate;", "uniform float iSampleRate;",
        "uniform vec3 iChannelResolution[4];", "uniform int iFrame;", "uniform float iTimeDelta;",
        "uniform float iFrameRate;", "uniform sampler2D iChannel0;",
        "uniform samplerCube iChannel1;", "uniform sampler3D iChannel2;",
        "uniform sampler2D iChannel3;", "#define HW_PERFORMANCE 1",
        "precision mediump sampler3D;"}) {
    EXPECT_NE(header.find(line), std::string::npos) << line;
  }
  EXPECT_NE(ShaderToyEpilogue(model::PassKind::kImage).find("vec4(shadertoy_color.xyz, 1.0)"),
            std::string::npos);
  EXPECT_EQ(ShaderToyEpilogue(model::PassKind::kBuffer).find("1.0)"), std::string::npos);
}

TEST(ShaderToyContractTest, TypicalImagePassCompilesAndLinks) {
  auto c = CompilePass(
      "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
      "  vec2 uv = fragCoord / iResolution.xy;\n"
      "  fragColor = vec4(uv, 0.5 + 0.5 * sin(iTime), 1.0) * texture(iChannel0, uv);\n"
      "}");  // no final newline: the next generated part must not join this line
  EXPECT_TRUE(c->result.Accepted(true)) << Rules(c->result.diagnostics);
  EXPECT_TRUE(c->result.diagnostics.empty()) << Rules(c->result.diagnostics);
}

TEST(ShaderToyContractTest, MediumpPrecisionStatementCompilesCleanly) {
  auto c = CompilePass(
      "precision mediump float;\n"
      "void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(1.0); }\n");
  EXPECT_TRUE(c->result.Accepted(true)) << Rules(c->result.diagnostics);
  EXPECT_TRUE(c->result.diagnostics.empty()) << Rules(c->result.diagnostics);
}

TEST(ShaderToyContractTest, UserMacrosDoNotBreakTheGeneratedMain) {
  auto c = CompilePass(
      "#define color vec3(1.0)\n#define t iTime\n#define c 2.0\n"
      "void mainImage(out vec4 O, in vec2 U) { O = vec4(color * t * c, 1.0); }\n");
  EXPECT_TRUE(c->result.Accepted(true)) << Rules(c->result.diagnostics);
}

TEST(ShaderToyContractTest, EntryPointDefinedAsAMacroIsCalledLikeOnTheSite) {
  // Corpus shader wddcz2 defines mainImage in Common as a function-like macro.
  auto c =
      CompilePass("vec4 Main(vec2 uv) { return vec4(uv, 0.0, 1.0); }\n", model::PassKind::kImage,
                  "vec4 Main(vec2 uv);\n#define mainImage(color, coord) (color = Main(coord))\n");
  EXPECT_TRUE(c->result.Accepted(true)) << Rules(c->result.diagnostics);
}

TEST(ShaderToyContractTest, ErrorBehindTheHeaderLandsOnTheUserLine) {
  auto c = CompilePass(
      "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
      "  fragColor = vec4(fragCoord, iTime, undefinedThing);\n"
      "}\n");
  ASSERT_EQ(c->result.diagnostics.size(), 1u) << Rules(c->result.diagnostics);
  const auto& d = c->result.diagnostics[0];
  EXPECT_EQ(d.rule_id, "glslang/undeclared-identifier");
  EXPECT_EQ(d.range.file, c->pass);
  EXPECT_EQ(Where(c->sources, d.range), (LineColumn{2, 38}));
}

TEST(ShaderToyContractTest, ErrorInCommonLandsInCommon) {
  auto c = CompilePass("void mainImage(out vec4 o, in vec2 u) { o = vec4(helper()); }\n",
                       model::PassKind::kImage,
                       "// shared code\nfloat helper() {\n  return pow(2.0, 2);\n}\n");
  ASSERT_FALSE(c->result.diagnostics.empty());
  const auto& d = c->result.diagnostics[0];
  EXPECT_EQ(d.rule_id, "glslang/no-matching-overload");
  EXPECT_EQ(d.range.file, c->common);
  EXPECT_EQ(Where(c->sources, d.range), (LineColumn{3, 10}));
}

TEST(ShaderToyContractTest, MacroFromCommonIsVisibleInThePass) {
  auto c = CompilePass("void mainImage(out vec4 o, in vec2 u) {\n  o = vec4(TWICE(1.0) + x);\n}\n",
                       model::PassKind::kImage, "#define TWICE(v) (2.0 * (v))\n");
  ASSERT_EQ(c->result.diagnostics.size(), 1u) << Rules(c->result.diagnostics);
  EXPECT_EQ(c->result.diagnostics[0].range.file, c->pass);
  EXPECT_EQ(Where(c->sources, c->result.diagnostics[0].range), (LineColumn{2, 25}));
}

TEST(ShaderToyContractTest, MissingMainImageIsAUserErrorAtTheFile) {
  auto c = CompilePass("void mainImg(out vec4 o, in vec2 u) { o = vec4(1.0); }\n");
  EXPECT_TRUE(c->result.compiled);
  EXPECT_FALSE(c->result.linked);
  ASSERT_EQ(c->result.diagnostics.size(), 1u) << Rules(c->result.diagnostics);
  EXPECT_EQ(c->result.diagnostics[0].rule_id, "glslang/missing-entry-point");
  EXPECT_EQ(c->result.diagnostics[0].range, (SourceRange{c->pass, 0, 0}));
}

TEST(ShaderToyContractTest, WrongParametersPointAtTheUsersMainImage) {
  auto c = CompilePass("\nvoid mainImage(out vec4 o, in vec2 u, float k) { o = vec4(k); }\n");
  ASSERT_EQ(c->result.diagnostics.size(), 1u) << Rules(c->result.diagnostics);
  EXPECT_EQ(c->result.diagnostics[0].rule_id, "glslang/missing-entry-point");
  EXPECT_EQ(Where(c->sources, c->result.diagnostics[0].range), (LineColumn{2, 6}));
}

TEST(ShaderToyContractTest, WrongReturnTypeIsAnEntryPointMismatchNotInternal) {
  auto c =
      CompilePass("vec4 mainImage(out vec4 o, in vec2 u) {\n  o = vec4(1.0);\n  return o;\n}\n");
  ASSERT_EQ(c->result.diagnostics.size(), 1u) << Rules(c->result.diagnostics);
  const auto& d = c->result.diagnostics[0];
  EXPECT_EQ(d.rule_id, "glslang/entry-point-mismatch");
  EXPECT_EQ(d.range.file, c->pass);
  EXPECT_EQ(Where(c->sources, d.range), (LineColumn{1, 6}));
}

TEST(ShaderToyContractTest, UnclosedBraceIsIncompleteUserCode) {
  auto c = CompilePass("void mainImage(out vec4 o, in vec2 u) {\n  o = vec4(1.0);\n");
  ASSERT_EQ(c->result.diagnostics.size(), 1u) << Rules(c->result.diagnostics);
  const auto& d = c->result.diagnostics[0];
  EXPECT_EQ(d.rule_id, "glslang/incomplete-code");
  EXPECT_EQ(d.range.file, c->pass);
  EXPECT_FALSE(d.notes.empty());  // the cascade is kept, not hidden
}

// A '}' lost from a multi-line #define: the text is balanced, the expanded code is not
// (found by the mutation sweep: it was internal/generated-code, exit 3).
TEST(ShaderToyContractTest, BraceLostInAMacroIsIncompleteUserCode) {
  auto c = CompilePass(
      "#define OPEN(x) { \\\n  float m = x; \\\n\n"
      "void mainImage(out vec4 o, in vec2 u) {\n  OPEN(1.0)\n  o = vec4(1.0);\n}\n");
  bool incomplete = false;
  for (const Diagnostic& d : c->result.diagnostics) {
    EXPECT_NE(d.rule_id, "internal/generated-code") << d.message;
    incomplete = incomplete || d.rule_id == "glslang/incomplete-code";
  }
  EXPECT_TRUE(incomplete) << Rules(c->result.diagnostics);
}

// A user macro that rewrites the site's own main() is the user's error, at the
// macro (it fails on the site too), never internal/generated-code.
TEST(ShaderToyContractTest, AMacroRewritingTheWrapperIsBlamedOnTheMacro) {
  const std::string code =
      "#define mainImage(o, u) mainImage(out vec4 o, in vec2 u)\n"
      "void mainImage(o, u) { o = vec4(u, 0, 1); }\n";
  auto c = CompilePass(code);
  ASSERT_FALSE(c->result.diagnostics.empty());
  for (const auto& d : c->result.diagnostics) EXPECT_NE(d.rule_id, "internal/generated-code");
  const auto& d = c->result.diagnostics[0];
  EXPECT_EQ(d.rule_id, "shadertoy/macro-rewrites-wrapper");
  EXPECT_EQ(d.severity, Severity::kError);
  EXPECT_EQ(d.range.file, c->pass);
  EXPECT_EQ(d.range.begin, 8u);  // the macro's name
  EXPECT_NE(d.message.find("mainImage(shadertoy_color, gl_FragCoord.xy);"), std::string::npos);
}

// Common code whose last declaration lacks its ';' (or has one too many) fails
// where the next text starts: the error goes on Common's last token.
TEST(ShaderToyContractTest, AnUnfinishedEndOfCommonIsBlamedOnCommon) {
  auto missing = CompilePass("void mainImage(out vec4 o, in vec2 u) { o = vec4(1); }\n",
                             model::PassKind::kImage, "struct S { float a; }");
  ASSERT_FALSE(missing->result.diagnostics.empty());
  for (const auto& d : missing->result.diagnostics) {
    EXPECT_NE(d.rule_id, "internal/generated-code");
  }
  const auto& first = missing->result.diagnostics[0];
  EXPECT_EQ(first.range.file, missing->pass);
  ASSERT_EQ(first.notes.size(), 1u);
  EXPECT_EQ(first.notes[0].range.file, missing->common);
  EXPECT_EQ(first.notes[0].range.begin, 20u);  // Common's closing brace

  auto extra = CompilePass("void mainImage(out vec4 o, in vec2 u) { o = vec4(1); }\n",
                           model::PassKind::kImage, "float f() { return 1.0; };");
  ASSERT_EQ(extra->result.diagnostics.size(), 1u) << Rules(extra->result.diagnostics);
  EXPECT_EQ(extra->result.diagnostics[0].range.file, extra->common);
  EXPECT_EQ(extra->result.diagnostics[0].range.begin, 25u);  // the extra ';'

  // Common checked on its own, as the site's wrapper follows it.
  auto alone = CompilePass("struct S { float a; }");
  const auto syntax =
      std::find_if(alone->result.diagnostics.begin(), alone->result.diagnostics.end(),
                   [](const Diagnostic& d) { return d.rule_id == "glslang/syntax-error"; });
  ASSERT_NE(syntax, alone->result.diagnostics.end()) << Rules(alone->result.diagnostics);
  EXPECT_EQ(syntax->range.file, alone->pass);
  EXPECT_EQ(syntax->range.begin, 20u);
}

// Common code whose last line ends in a line continuation must not swallow the
// site's '#ifndef mainImage' that follows it (seen on real passes).
TEST(ShaderToyContractTest, ALineContinuationAtTheEndOfCommonStaysInCommon) {
  auto c = CompilePass("void mainImage(out vec4 o, in vec2 u) { o = vec4(f()); }\n",
                       model::PassKind::kImage, "float f() { return 1.0; }\\\n");
  EXPECT_TRUE(c->result.Accepted(true)) << Rules(c->result.diagnostics);
  auto alone = CompilePass("void mainImage(out vec4 o, in vec2 u) { o = vec4(1); }\\\n");
  EXPECT_TRUE(alone->result.Accepted(true)) << Rules(alone->result.diagnostics);
}

TEST(ShaderToyContractTest, ChannelTypesFollowTheInputs) {
  const std::string code =
      "void mainImage(out vec4 o, in vec2 u) { o = texture(iChannel1, vec3(u, 1.0)); }\n";
  EXPECT_FALSE(CompilePass(code)->result.compiled);
  auto cube = CompilePass(code, model::PassKind::kImage, "",
                          {model::ChannelKind::k2D, model::ChannelKindFromCtype("cubemap"),
                           model::ChannelKind::k2D, model::ChannelKind::k2D});
  EXPECT_TRUE(cube->result.Accepted(true)) << Rules(cube->result.diagnostics);
  auto volume = CompilePass(code, model::PassKind::kImage, "",
                            {model::ChannelKind::k2D, model::ChannelKindFromCtype("volume"),
                             model::ChannelKind::k2D, model::ChannelKind::k2D});
  EXPECT_TRUE(volume->result.Accepted(true)) << Rules(volume->result.diagnostics);
}

TEST(ShaderToyContractTest, SoundAndCubePassesHaveTheirOwnMains) {
  auto sound = CompilePass("vec2 mainSound(int samp, float time) { return vec2(sin(time)); }\n",
                           model::PassKind::kSound);
  EXPECT_TRUE(sound->result.Accepted(true)) << Rules(sound->result.diagnostics);
  auto cube = CompilePass(
      "void mainCubemap(out vec4 o, in vec2 f, in vec3 ro, in vec3 rd) { o = vec4(rd, 1.0); }\n",
      model::PassKind::kCube);
  EXPECT_TRUE(cube->result.Accepted(true)) << Rules(cube->result.diagnostics);
  auto wrong = CompilePass("void mainImage(out vec4 o, in vec2 u) { o = vec4(1.0); }\n",
                           model::PassKind::kSound);
  ASSERT_EQ(wrong->result.diagnostics.size(), 1u);
  EXPECT_EQ(wrong->result.diagnostics[0].rule_id, "glslang/missing-entry-point");
}

TEST(ShaderToyContractTest, NamesFromTheCorpusJson) {
  EXPECT_EQ(model::ParsePassKind("buffer"), model::PassKind::kBuffer);
  EXPECT_EQ(model::ParsePassKind("common"), model::PassKind::kCommon);
  EXPECT_EQ(model::ChannelKindFromCtype("texture"), model::ChannelKind::k2D);
  EXPECT_EQ(model::ChannelKindFromCtype("keyboard"), model::ChannelKind::k2D);
}

}  // namespace
}  // namespace shaderport::validate
