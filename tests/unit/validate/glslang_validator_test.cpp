#include "validate/glslang_validator.h"

#include <gtest/gtest.h>

#include <thread>

#include "validate/validate_test_util.h"

namespace shaderport::validate {
namespace {

using testing::ValidateText;
using testing::Where;

TEST(GlslangValidatorTest, CleanWebGl1AndWebGl2ShadersPass) {
  SourceManager sources;
  auto webgl1 = ValidateText(sources,
                             "precision mediump float;\nvarying vec2 v;\n"
                             "void main() { gl_FragColor = vec4(v, 0.0, 1.0); }\n");
  EXPECT_TRUE(webgl1.Accepted(false));
  EXPECT_TRUE(webgl1.diagnostics.empty());
  auto webgl2 = ValidateText(sources,
                             "#version 300 es\nprecision highp float;\nout vec4 o;\n"
                             "void main() { o = vec4(1.0); }\n");
  EXPECT_TRUE(webgl2.Accepted(false));
  EXPECT_TRUE(webgl2.diagnostics.empty());
}

TEST(GlslangValidatorTest, ErrorInPlainWebGl2FileLandsOnLineAndColumn) {
  SourceManager sources;
  const auto result = ValidateText(sources,
                                   "#version 300 es\n"
                                   "precision highp float;\n"
                                   "out vec4 o;\n"
                                   "void main() {\n"
                                   "  float x = 1;\n"
                                   "  o = vec4(x) * undefinedThing;\n"
                                   "}\n");
  EXPECT_FALSE(result.compiled);
  ASSERT_GE(result.diagnostics.size(), 2u);
  EXPECT_EQ(result.diagnostics[0].rule_id, "glslang/type-mismatch");
  EXPECT_EQ(Where(sources, result.diagnostics[0].range), (LineColumn{5, 11}));
  EXPECT_EQ(result.diagnostics[0].range.Size(), 1u);  // the '='
  EXPECT_EQ(result.diagnostics[0].message, "'=': cannot convert from 'const int' to 'highp float'");
  EXPECT_EQ(result.diagnostics[1].rule_id, "glslang/undeclared-identifier");
  EXPECT_EQ(Where(sources, result.diagnostics[1].range), (LineColumn{6, 17}));
  EXPECT_EQ(result.diagnostics[1].range.Size(), std::string("undefinedThing").size());
}

// glslang numbers lines as #line says: `#line 4294967295` made the next line -1 and put
// the finding on 1:1 ("p1:-1"), `#line 10` two lines too far. Findings are located by
// the file's own lines.
TEST(GlslangValidatorTest, LineDirectivesDoNotMoveFindings) {
  for (const std::string directive : {"#line 4294967295", "#line 10", "  #  line 7 3"}) {
    SourceManager sources;
    const auto result = ValidateText(sources, "#version 300 es\n" + directive +
                                                  "\nprecision highp float;\nout vec4 o;\n"
                                                  "void main() { o = vec4(undefinedThing); }\n");
    ASSERT_FALSE(result.diagnostics.empty()) << directive;
    EXPECT_EQ(result.diagnostics[0].rule_id, "glslang/undeclared-identifier") << directive;
    EXPECT_EQ(Where(sources, result.diagnostics[0].range), (LineColumn{5, 24})) << directive;
    EXPECT_EQ(result.diagnostics[0].message.find("p1:"), std::string::npos);
  }
}

TEST(GlslangValidatorTest, EveryErrorIsReportedNotOnlyTheFirst) {
  SourceManager sources;
  const auto result = ValidateText(sources,
                                   "#version 300 es\nprecision highp float;\nout vec4 o;\n"
                                   "void main() {\n  a = 1.0;\n  b = 2.0;\n  c = 3.0;\n}\n");
  ASSERT_EQ(result.diagnostics.size(), 3u);
  for (uint32_t i = 0; i < 3; ++i) {
    EXPECT_EQ(Where(sources, result.diagnostics[i].range), (LineColumn{5 + i, 3}));
  }
}

TEST(GlslangValidatorTest, QuotedWordNotOnTheLineFallsBackToTheWholeLine) {
  SourceManager sources;
  // glslang quotes 'texture2D' and then 'assign' for the same line; 'assign' is not a token.
  const auto result =
      ValidateText(sources,
                   "#version 300 es\nprecision highp float;\nuniform sampler2D s;\n"
                   "out vec4 o;\nvoid main() {\n    o = texture2D(s, vec2(0.5));  \n}\n");
  ASSERT_EQ(result.diagnostics.size(), 2u);
  EXPECT_EQ(Where(sources, result.diagnostics[0].range), (LineColumn{6, 9}));
  EXPECT_EQ(Where(sources, result.diagnostics[1].range), (LineColumn{6, 5}));
  const auto& range = result.diagnostics[1].range;
  EXPECT_EQ(sources.Get(range.file).Text().substr(range.begin, range.Size()),
            "o = texture2D(s, vec2(0.5));");
}

TEST(GlslangValidatorTest, ErrorsAfterAndInsideMacrosKeepTheirLines) {
  SourceManager sources;
  const auto result = ValidateText(sources,
                                   "#version 300 es\n"
                                   "precision highp float;\n"
                                   "#define SCALE(x) \\\n"
                                   "  ((x) * missingFactor)\n"
                                   "out vec4 o;\n"
                                   "void main() {\n"
                                   "  float v = SCALE(2.0);\n"
                                   "  o = vec4(v) + bad;\n"
                                   "}\n");
  ASSERT_EQ(result.diagnostics.size(), 2u);
  // The use of the macro is on line 7; the unknown name is in its body, so the whole line.
  EXPECT_EQ(result.diagnostics[0].rule_id, "glslang/undeclared-identifier");
  EXPECT_EQ(Where(sources, result.diagnostics[0].range), (LineColumn{7, 3}));
  // After a macro with a line continuation the line count is unchanged.
  EXPECT_EQ(Where(sources, result.diagnostics[1].range), (LineColumn{8, 17}));
}

TEST(GlslangValidatorTest, LinkingReportsAMissingMain) {
  SourceManager sources;
  const SourceFile& file = sources.Add("user.frag", "precision mediump float;\nvoid f() {}\n");
  ValidationRequest request;
  request.parts.push_back({file.Name(), file.Text(), file.Id(), PartKind::kUser});
  request.link = true;
  const auto result = ValidateWithGlslang(request);
  EXPECT_TRUE(result.compiled);
  EXPECT_FALSE(result.linked);
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].rule_id, "glslang/missing-entry-point");
  EXPECT_EQ(result.diagnostics[0].range, (SourceRange{file.Id(), 0, 0}));
}

TEST(GlslangValidatorTest, ErrorInGeneratedPartIsInternalAndStaysThere) {
  SourceManager sources;
  const SourceFile& header =
      sources.Add("test-header", "#version 300 es\nprecision highp float;\nint broken = ;\n", true);
  const SourceFile& user =
      sources.Add("user.frag", "out vec4 o;\nvoid main() { o = vec4(1.0); }\n");
  ValidationRequest request;
  request.parts.push_back({header.Name(), header.Text(), header.Id(), PartKind::kGenerated});
  request.parts.push_back({user.Name(), user.Text(), user.Id(), PartKind::kUser});
  const auto result = ValidateWithGlslang(request);
  ASSERT_FALSE(result.diagnostics.empty());
  EXPECT_EQ(result.diagnostics[0].rule_id, "internal/generated-code");
  EXPECT_EQ(result.diagnostics[0].range.file, header.Id());
  EXPECT_EQ(Where(sources, result.diagnostics[0].range).line, 3u);
}

TEST(GlslangValidatorTest, DeepNestingDoesNotCrash) {
  SourceManager sources;
  const std::string deep = std::string(20000, '(') + "1.0" + std::string(20000, ')');
  const auto result = ValidateText(sources,
                                   "#version 300 es\nprecision highp float;\nout vec4 o;\n"
                                   "void main() { o = vec4(" +
                                       deep + "); }\n");
  EXPECT_FALSE(result.crashed);
  EXPECT_FALSE(result.compiled);  // glslang's parser stack is limited: an error, not a crash
}

TEST(GlslangValidatorTest, InputKnownToCrashGlslangIsReportedNotSuffered) {
  // WebGL CTS conformance/glsl/preprocessor/macro-expansion-tricky.html, case 0.
  SourceManager sources;
  const auto result = ValidateText(sources,
                                   "\n#define m(a)\n#define a m((a)\na)\n\n"
                                   "precision mediump float;\nvoid main() {\n"
                                   "    gl_FragColor = vec4(0.0);\n}\n");
  EXPECT_TRUE(result.crashed);
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].rule_id, "glslang/crashed");
}

TEST(GlslangValidatorTest, UnbalancedMacroThatDoesNotCrashIsValidatedOutOfProcess) {
  SourceManager sources;
  const auto result = ValidateText(sources,
                                   "precision mediump float;\n#define OPEN vec4(\n"
                                   "void main() { gl_FragColor = OPEN 1.0); }\n");
  EXPECT_FALSE(result.crashed);
  EXPECT_TRUE(result.compiled);
}

TEST(GlslangValidatorTest, ConcurrentCallsGiveTheSameAnswers) {
  const std::string bad =
      "#version 300 es\nprecision highp float;\nout vec4 o;\n"
      "void main() { float x = 1; o = vec4(x); }\n";
  std::vector<std::thread> threads;
  std::atomic<int> wrong = 0;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&] {
      for (int i = 0; i < 25; ++i) {
        SourceManager sources;
        const auto result = ValidateText(sources, bad);
        if (result.compiled || result.diagnostics.size() != 1 ||
            Where(sources, result.diagnostics[0].range) != LineColumn{4, 23}) {
          ++wrong;
        }
      }
    });
  }
  for (auto& thread : threads) thread.join();
  EXPECT_EQ(wrong, 0);
}

}  // namespace
}  // namespace shaderport::validate
