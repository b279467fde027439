// Golden cases of the portability/* rules, under tests/rules/portability-<rule>/:
//   <case>.frag|.vert   WebGL code (GLSL ES 1.00 unless it has #version 300 es)
//   <case>.glsl         ShaderToy Image-pass code (the site's uniforms, mainImage)
//   <case>.diag         what the rule alone reports, with its fix-its
//   <case>.out.<ext>    the input after `fix` with every portability/* rule (fix engine)
// Every output compiles with glslang in its dialect (ShaderToy under the site's
// contract), and fixing it again changes nothing. Cases named keep-* expect no
// finding; unfixable-* cases keep their finding without a fix. After the fix no
// uninitialized-read finding is left unless the case is unfixable-*.
// SHADERPORT_UPDATE_GOLDENS=1 rewrites the expected files.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "diag/rule_catalog.h"
#include "finding_format.h"
#include "golden.h"
#include "rules/golden_cases.h"
#include "typing_test_support.h"

namespace shaderport::portability_test {
namespace {

using shaderport::testing::FormatFindings;
using shaderport::testing::MatchesGolden;
using shaderport::testing::ReadWholeFile;
using typing_test::Kind;

namespace fs = std::filesystem;

constexpr std::string_view kUninitialized = "portability/uninitialized-read";
constexpr std::string_view kIndexRange = "portability/index-range";
constexpr std::string_view kMissingReturn = "portability/missing-return";

std::vector<const rule::Rule*> PortabilityRules() {
  std::vector<const rule::Rule*> selected;
  for (const rule::Rule* r : rules::AllRules()) {
    if (r->Info().id.starts_with("portability/")) selected.push_back(r);
  }
  return selected;
}

using Case = testing::GoldenCase;

std::vector<Case> AllCases() { return testing::GoldenCases("portability"); }

// `shaderport fix` with the portability rules only.
rule::FixEngineResult FixPortability(const std::string& text, Kind kind, model::Stage stage) {
  const SourceFile file(0, "input", text);
  rule::FixEngineOptions options;
  options.settings = typing_test::FixSettings(kind, stage);
  options.rules = PortabilityRules();
  options.analyze = typing_test::AnalyzerFor(kind, stage);
  return rule::RunFixEngine(file, options);
}

TEST(PortabilityGolden, EveryRuleHasCases) {
  const std::vector<Case> cases = AllCases();
  auto count = [&](std::string_view id) {
    return std::count_if(cases.begin(), cases.end(),
                         [&](const Case& c) { return c.rule_id == id; });
  };
  EXPECT_GE(count(kUninitialized), 8);
  EXPECT_GE(count(kIndexRange), 6);
  EXPECT_GE(count(kMissingReturn), 3);
  EXPECT_GE(count("portability/infinite-loop"), 8);
  EXPECT_GE(count("portability/output-never-written"), 6);
  EXPECT_EQ(PortabilityRules().size(), 5u);
}

TEST(PortabilityGolden, Cases) {
  const std::vector<Case> cases = AllCases();
  ASSERT_FALSE(cases.empty());
  for (const Case& c : cases) {
    SCOPED_TRACE(c.input.string());
    const rule::Rule* r = rules::FindRule(c.rule_id);
    ASSERT_NE(r, nullptr) << c.rule_id;
    const std::string ext = c.input.extension().string();
    const Kind kind = ext == ".glsl" ? Kind::kShaderToy : Kind::kWebGL;
    const model::Stage stage = ext == ".vert" ? model::Stage::kVertex : model::Stage::kFragment;
    const std::string text = ReadWholeFile(c.input);
    const std::string stem = c.input.stem().string();

    const DiagnosticList own = typing_test::RunOneRule(*r, text, kind, stage);
    fs::path diag_path = c.input;
    diag_path.replace_extension(".diag");
    EXPECT_TRUE(MatchesGolden(FormatFindings(text, own), diag_path));
    EXPECT_EQ(own.empty(), stem.starts_with("keep-")) << FormatFindings(text, own);
    for (const Diagnostic& d : own) {
      EXPECT_EQ(d.rule_id, c.rule_id);
      EXPECT_EQ(d.severity, Severity::kWarning);
      if (stem.starts_with("unfixable-")) {
        EXPECT_TRUE(d.fixes.empty());
      }
    }

    const rule::FixEngineResult fixed = FixPortability(text, kind, stage);
    fs::path out_path = c.input;
    out_path.replace_extension(".out" + ext);
    EXPECT_TRUE(MatchesGolden(fixed.text, out_path));
    EXPECT_TRUE(fixed.converged);
    bool accepted = false;
    const validate::ValidationResult result =
        typing_test::Compile(fixed.text, kind, stage, &accepted);
    EXPECT_TRUE(accepted) << fixed.text << typing_test::Messages(result);
    EXPECT_EQ(FixPortability(fixed.text, kind, stage).text, fixed.text)
        << "fixing twice changed it";
    if (!stem.starts_with("unfixable-")) {
      for (const Diagnostic& d : fixed.remaining) {
        EXPECT_NE(d.rule_id, kUninitialized) << FormatFindings(text, fixed.remaining);
      }
    }
  }
}

// The lint scope: `check` runs both rules, `fix` and `port` apply their fixes.
TEST(PortabilityRules, ScopeLintRunsInCheckFixAndPort) {
  for (std::string_view id :
       {kUninitialized, kIndexRange, std::string_view("portability/infinite-loop"),
        std::string_view("portability/output-never-written")}) {
    const rule::Rule* r = rules::FindRule(id);
    ASSERT_NE(r, nullptr) << id;
    EXPECT_EQ(r->Info().scope, rule::RuleScope::kLint) << id;
    for (const auto& selected : {rules::CheckRules(), rules::RulesForMode(rule::PortMode::kFix),
                                 rules::RulesForMode(rule::PortMode::kPort)}) {
      EXPECT_NE(std::find(selected.begin(), selected.end(), r), selected.end()) << id;
    }
    const RuleDescription* entry = shaderport::FindRule(id);
    EXPECT_NE(entry, nullptr) << id << " is not in the catalog";
  }
  // kCheck rules still never fix, and kAlways rules still run in both modes.
  for (const rule::Rule* r : rules::RulesForMode(rule::PortMode::kFix)) {
    EXPECT_NE(r->Info().scope, rule::RuleScope::kCheck) << r->Info().id;
    EXPECT_NE(r->Info().scope, rule::RuleScope::kPort) << r->Info().id;
  }
}

TEST(PortabilityRules, CatalogCitesTheSpecAndTheBrowser) {
  const RuleDescription* uninitialized = shaderport::FindRule(kUninitialized);
  ASSERT_NE(uninitialized, nullptr);
  EXPECT_NE(uninitialized->help.find("section 6.1.1"), std::string_view::npos);
  EXPECT_NE(uninitialized->help.find("ANGLE"), std::string_view::npos);
  const RuleDescription* index_range = shaderport::FindRule(kIndexRange);
  ASSERT_NE(index_range, nullptr);
  EXPECT_NE(index_range->help.find("ANGLE"), std::string_view::npos);
}

// `shaderport fix` of ShaderToy code with every rule of the mode zero-initialises
// what the browser would, and the result still compiles on the site.
TEST(PortabilityRules, FixModeWritesTheBrowsersZeros) {
  const std::string text =
      "void mainImage(out vec4 O, in vec2 U) {\n"
      "  vec4 col2;\n"
      "  col2 += vec4(0.5);\n"
      "  O += col2;\n"
      "}\n";
  const SourceFile file(0, "input", text);
  rule::FixEngineOptions options;
  options.settings = typing_test::FixSettings(Kind::kShaderToy, model::Stage::kFragment);
  options.rules = rules::RulesForMode(rule::PortMode::kFix);
  options.analyze = typing_test::AnalyzerFor(Kind::kShaderToy, model::Stage::kFragment);
  const rule::FixEngineResult fixed = rule::RunFixEngine(file, options);
  EXPECT_EQ(fixed.text,
            "void mainImage(out vec4 O, in vec2 U) {\n"
            "  O = vec4(0.0);\n"
            "  vec4 col2 = vec4(0.0);\n"
            "  col2 += vec4(0.5);\n"
            "  O += col2;\n"
            "}\n");
  bool accepted = false;
  typing_test::Compile(fixed.text, Kind::kShaderToy, model::Stage::kFragment, &accepted);
  EXPECT_TRUE(accepted);
}

// Deep left-associative chains are walked without recursion, and nothing is reported there.
TEST(PortabilityRules, LongExpressionChainsDoNotOverflow) {
  std::string sum = "x";
  for (int i = 0; i < 20000; ++i) sum += " + x";
  const std::string text =
      "void mainImage(out vec4 O, in vec2 U) {\n  float x = 1.0;\n  O = vec4(" + sum + ");\n}\n";
  for (const rule::Rule* r : PortabilityRules()) {
    const DiagnosticList found =
        typing_test::RunOneRule(*r, text, Kind::kShaderToy, model::Stage::kFragment);
    EXPECT_TRUE(found.empty()) << FormatFindings(text, found);
  }
}

// One '}' missing: the parser ends f's body at the end of the file, on mainImage's
// '}'. A return put before it landed in mainImage, and `fix -i` wrote 100 of them.
TEST(PortabilityRules, MissingReturnLeavesABodyThatIsNotClosed) {
  const std::string text =
      "float f(float x) {\n  if (x > 0.0) {\n    return x;\n}\n"
      "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
      "  fragColor = vec4(f(fragCoord.x));\n}\n";
  const rule::Rule* r = rules::FindRule(kMissingReturn);
  ASSERT_NE(r, nullptr);
  EXPECT_TRUE(typing_test::RunOneRule(*r, text, Kind::kShaderToy, model::Stage::kFragment).empty());
  const rule::FixEngineResult fixed =
      FixPortability(text, Kind::kShaderToy, model::Stage::kFragment);
  EXPECT_TRUE(fixed.converged);
  EXPECT_EQ(fixed.text, text);
}

}  // namespace
}  // namespace shaderport::portability_test
