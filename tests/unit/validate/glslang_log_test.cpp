#include "validate/glslang_log.h"

#include <gtest/gtest.h>

#include "diag/rule_catalog.h"
#include "validate/glslang_rules.h"

namespace shaderport::validate {
namespace {

TEST(GlslangLogTest, ParsesLocationTokenAndTextWithOddSpacing) {
  const auto messages = ParseGlslangLog(
      "ERROR: p1:5: '=' :  cannot convert from ' const float' to ' temp highp 3-component vector "
      "of float'\n"
      "ERROR: p1:6: 'pow' : no matching overloaded function found \n"
      "WARNING: p0:2: '#extension' : extension not supported: GL_FOO\n");
  ASSERT_EQ(messages.size(), 3u);
  EXPECT_EQ(messages[0].severity, Severity::kError);
  EXPECT_EQ(messages[0].part, "p1");
  EXPECT_EQ(messages[0].line, 5u);
  EXPECT_EQ(messages[0].token, "=");
  EXPECT_EQ(messages[0].text,
            "cannot convert from ' const float' to ' temp highp 3-component vector of float'");
  EXPECT_EQ(messages[1].token, "pow");
  EXPECT_EQ(messages[1].text, "no matching overloaded function found");
  EXPECT_EQ(messages[2].severity, Severity::kWarning);
  EXPECT_EQ(messages[2].part, "p0");
}

TEST(GlslangLogTest, SkipsSummaryLinesAndJoinsContinuations) {
  const auto messages = ParseGlslangLog(
      "ERROR: 0:3: '' : compilation terminated \n"
      "ERROR: 2 compilation errors.  No code generated.\n\n\n"
      "ERROR: Linking fragment stage: No function definition (body) found: \n"
      "    mainImage(vf4;vf2;\n");
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].part, "");
  EXPECT_EQ(messages[0].line, 0u);
  EXPECT_EQ(messages[0].text,
            "Linking fragment stage: No function definition (body) found: mainImage(vf4;vf2;");
}

TEST(GlslangLogTest, TokenMayContainQuotesAndColons) {
  const auto messages = ParseGlslangLog("ERROR: p2:7: ''' : unexpected ' : token\n");
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].token, "'");
  EXPECT_EQ(messages[0].text, "unexpected ' : token");
}

TEST(GlslangRulesTest, ClassifiesKnownMessages) {
  auto rule = [](std::string token, std::string text) {
    return std::string(ClassifyGlslangMessage({Severity::kError, "p0", 1, token, text}));
  };
  EXPECT_EQ(rule("x", "undeclared identifier"), "glslang/undeclared-identifier");
  EXPECT_EQ(rule("pow", "no matching overloaded function found"), "glslang/no-matching-overload");
  EXPECT_EQ(rule("=", "cannot convert from ' const int' to ' temp float'"),
            "glslang/type-mismatch");
  EXPECT_EQ(rule("*", "wrong operand types: no operation '*' exists ... cannot convert"),
            "glslang/wrong-operand-types");
  EXPECT_EQ(rule("varying", "Reserved word."), "glslang/reserved-word");
  EXPECT_EQ(rule("float", "type requires declaration of default precision qualifier"),
            "glslang/missing-precision");
  EXPECT_EQ(rule("", "syntax error, unexpected IDENTIFIER"), "glslang/syntax-error");
  EXPECT_EQ(rule("f", "redefinition"), "glslang/redefinition");
  EXPECT_EQ(rule("", "array size must be a constant integer expression"),
            "glslang/constant-expression-required");
  EXPECT_EQ(rule("", "Linking fragment stage: Missing entry point: Each stage requires one"),
            "glslang/missing-entry-point");
  EXPECT_EQ(rule("#version", "bad profile name"), "glslang/preprocessor");
  EXPECT_EQ(rule("x", "something new"), "glslang/error");
  EXPECT_EQ(ClassifyGlslangMessage({Severity::kWarning, "p0", 1, "x", "something new"}),
            "glslang/warning");
}

TEST(GlslangRulesTest, EveryRuleIdIsInTheCatalog) {
  for (const char* text :
       {"undeclared identifier", "no matching overloaded function found", "wrong operand types",
        "cannot convert", "default precision qualifier", "non-constant global initializer",
        "Reserved word.", "syntax error", "Missing entry point", "redefinition",
        "constant expression required", "no longer supported", "Too few args in Macro", "x"}) {
    for (Severity severity : {Severity::kError, Severity::kWarning}) {
      const auto id = ClassifyGlslangMessage({severity, "p0", 1, "", text});
      EXPECT_NE(FindRule(id), nullptr) << id;
    }
  }
  for (const char* id : {"glslang/entry-point-mismatch", "glslang/incomplete-code",
                         "glslang/crashed", "internal/generated-code"}) {
    EXPECT_NE(FindRule(id), nullptr) << id;
  }
}

TEST(GlslangRulesTest, TidiesSpacesAndStorageWords) {
  GlslangMessage message{Severity::kError, "p0", 5, "=",
                         "cannot convert from ' const float' to ' temp highp 3-component vector "
                         "of  float'"};
  EXPECT_EQ(TidyGlslangText(message),
            "'=': cannot convert from 'const float' to 'highp 3-component vector of float'");
  message = {Severity::kError, "p0", 5, "", "no operation '*' exists for ' global float'"};
  EXPECT_EQ(TidyGlslangText(message), "no operation '*' exists for 'float'");
}

}  // namespace
}  // namespace shaderport::validate
