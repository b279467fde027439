#include <gtest/gtest.h>

#include <string>

#include "driver/config/config.h"

namespace shaderport::driver {
namespace {

struct Parsed {
  SourceManager sources;
  ConfigResult result;
  explicit Parsed(std::string_view text, std::string_view path = "/proj/.shaderport.toml")
      : result(ParseConfig(text, path, sources)) {}

  // "line:col rule" for every diagnostic, to assert positions compactly.
  std::string Where(size_t i) const {
    const Diagnostic& d = result.diagnostics.at(i);
    const LineColumn at = sources.Get(d.range.file).LocationOf(d.range.begin);
    return std::to_string(at.line) + ":" + std::to_string(at.column) + " " + d.rule_id;
  }
};

TEST(ConfigParse, TheDocumentedExample) {
  Parsed parsed(R"toml(
[rules]
"input/empty" = "warning"   # off | note | warning | error
"suppression/*" = "off"
[check]
fail-on = "warning"
include = ["shaders/**"]
exclude = ["third_party/**", "**/*.gen.glsl"]
[[files]]
glob = "toy/**"
dialect = "shadertoy"
stage = "fragment"
[[files]]
glob = "web/*.vert"
dialect = "webgl1"
)toml");
  ASSERT_TRUE(parsed.result.diagnostics.empty()) << parsed.Where(0);
  const Config& config = parsed.result.config;
  EXPECT_EQ(config.directory, "/proj");
  ASSERT_EQ(config.rules.size(), 2u);
  EXPECT_EQ(config.rules[0].pattern, "input/empty");
  EXPECT_EQ(config.rules[0].level, RuleLevel::kWarning);
  EXPECT_EQ(config.rules[1].level, RuleLevel::kOff);
  EXPECT_EQ(config.fail_on, Severity::kWarning);
  EXPECT_EQ(config.include, std::vector<std::string>{"shaders/**"});
  EXPECT_EQ(config.exclude.size(), 2u);
  ASSERT_EQ(config.files.size(), 2u);
  EXPECT_EQ(config.files[0].dialect, Dialect::kShaderToy);
  EXPECT_EQ(config.files[0].stage, model::Stage::kFragment);
  EXPECT_EQ(config.files[1].dialect, Dialect::kWebGL1);
  EXPECT_FALSE(config.files[1].stage.has_value());
}

TEST(ConfigParse, EmptyFileIsTheDefault) {
  Parsed parsed("");
  EXPECT_TRUE(parsed.result.diagnostics.empty());
  EXPECT_EQ(parsed.result.config.fail_on, Severity::kError);
  EXPECT_TRUE(parsed.result.config.rules.empty());
}

TEST(ConfigParse, SyntaxErrorHasAPosition) {
  Parsed parsed("[rules]\n\"input/empty\" = \n");
  ASSERT_EQ(parsed.result.diagnostics.size(), 1u);
  EXPECT_EQ(parsed.result.diagnostics[0].severity, Severity::kError);
  EXPECT_EQ(parsed.Where(0).substr(0, 2), "2:");
  EXPECT_NE(parsed.Where(0).find("config/syntax-error"), std::string::npos);
}

TEST(ConfigParse, UnknownKeysAreWarningsAtTheKey) {
  Parsed parsed("[check]\nfail-on = \"error\"\nfial-on = \"x\"\n[rulez]\na = 1\n");
  ASSERT_EQ(parsed.result.diagnostics.size(), 2u);
  EXPECT_EQ(parsed.Where(0), "3:1 config/unknown-key");
  EXPECT_EQ(parsed.Where(1), "4:2 config/unknown-key");
  EXPECT_EQ(parsed.result.diagnostics[0].severity, Severity::kWarning);
  EXPECT_NE(parsed.result.diagnostics[0].message.find("'fial-on'"), std::string::npos);
}

TEST(ConfigParse, BadValuesAreErrorsAtTheValue) {
  Parsed parsed(
      "[rules]\n"
      "\"input/empty\" = \"loud\"\n"
      "\"not a rule\" = \"off\"\n"
      "\"input/binary\" = 3\n"
      "[check]\n"
      "fail-on = \"off\"\n"
      "include = \"shaders/**\"\n"
      "exclude = [\"../x\", 4]\n"
      "[[files]]\n"
      "glob = \"a/**\"\n"
      "dialect = \"webgl3\"\n"
      "[[files]]\n"
      "stage = \"vertex\"\n");
  std::vector<std::string> where;
  for (size_t i = 0; i < parsed.result.diagnostics.size(); ++i) where.push_back(parsed.Where(i));
  EXPECT_EQ(
      where,
      (std::vector<std::string>{
          "2:17 config/invalid-value", "3:1 config/invalid-value", "4:18 config/invalid-value",
          "6:11 config/invalid-value", "7:11 config/invalid-value", "8:12 config/invalid-value",
          "8:20 config/invalid-value", "11:11 config/invalid-value", "12:1 config/invalid-value"}));
  // Bad entries are dropped, good ones kept.
  EXPECT_TRUE(parsed.result.config.rules.empty());
  EXPECT_TRUE(parsed.result.config.files.empty());
  EXPECT_EQ(parsed.result.config.fail_on, Severity::kError);
}

TEST(ConfigParse, UnknownRuleIsAWarningButKept) {
  Parsed parsed("[rules]\n\"nosuch/rule\" = \"off\"\n");
  ASSERT_EQ(parsed.result.diagnostics.size(), 1u);
  EXPECT_EQ(parsed.Where(0), "2:1 config/unknown-rule");
  EXPECT_EQ(parsed.result.config.rules.size(), 1u);
}

TEST(ConfigParse, UnknownRuleSuggestsTheNearestId) {
  Parsed typo("[rules]\n\"glslang/missing-precison\" = \"off\"\n\"glslng/*\" = \"off\"\n");
  ASSERT_EQ(typo.result.diagnostics.size(), 2u);
  EXPECT_NE(typo.result.diagnostics[0].message.find("did you mean 'glslang/missing-precision'?"),
            std::string::npos)
      << typo.result.diagnostics[0].message;
  EXPECT_NE(typo.result.diagnostics[1].message.find("did you mean 'glslang/*'?"), std::string::npos)
      << typo.result.diagnostics[1].message;
  Parsed far("[rules]\n\"nosuch/rule\" = \"off\"\n");
  ASSERT_EQ(far.result.diagnostics.size(), 1u);
  EXPECT_EQ(far.result.diagnostics[0].message.find("did you mean"), std::string::npos);
}

TEST(ConfigParse, ColumnsAreBytesAfterMultiByteCharacters) {
  Parsed parsed("# é\n[check]\nfail-on = \"\xC3\xA9\"  \n");
  ASSERT_EQ(parsed.result.diagnostics.size(), 1u);
  EXPECT_EQ(parsed.Where(0), "3:11 config/invalid-value");
}

TEST(ConfigParse, WrongShapesDoNotCrash) {
  for (const char* text : {"rules = 1", "check = []", "files = 3", "files = [1, 2]",
                           "[[files]]\nglob = 1", "[rules.x]\ny = 1", "\xFF\xFE"}) {
    Parsed parsed(text);
    EXPECT_FALSE(parsed.result.diagnostics.empty()) << text;
  }
}

}  // namespace
}  // namespace shaderport::driver
