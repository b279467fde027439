// Golden cases of the typing/* rules, under tests/rules/typing-<rule>/:
//   <case>.frag|.vert   WebGL code (GLSL ES 1.00 unless it has #version 300 es)
//   <case>.glsl         ShaderToy Image-pass code (the site's uniforms, mainImage)
//   <case>.diag         what the rule alone reports, with its fix-its
//   <case>.out.<ext>    the input after `fix` with every typing/* rule (fix engine)
// Every output compiles with glslang in its dialect (ShaderToy under the site's
// contract), and fixing it again changes nothing. Cases named keep-* expect no
// finding; unfixable-* cases keep their finding without a fix and need not compile.
// SHADERPORT_UPDATE_GOLDENS=1 rewrites the expected files.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "finding_format.h"
#include "golden.h"
#include "rules/golden_cases.h"
#include "typing_test_support.h"

namespace shaderport::typing_test {
namespace {

using shaderport::testing::FormatFindings;
using shaderport::testing::MatchesGolden;
using shaderport::testing::ReadWholeFile;

namespace fs = std::filesystem;

using Case = testing::GoldenCase;

std::vector<Case> AllCases() { return testing::GoldenCases("typing"); }

TEST(TypingGolden, EveryRuleHasCases) {
  for (const rule::Rule* r : TypingRules()) {
    size_t count = 0;
    for (const Case& c : AllCases()) count += c.rule_id == r->Info().id;
    EXPECT_GE(count, 2u) << r->Info().id;
  }
  EXPECT_EQ(TypingRules().size(), 6u);
}

TEST(TypingGolden, Cases) {
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

    const DiagnosticList own = RunOneRule(*r, text, kind, stage);
    fs::path diag_path = c.input;
    diag_path.replace_extension(".diag");
    EXPECT_TRUE(MatchesGolden(FormatFindings(text, own), diag_path));
    EXPECT_EQ(own.empty(), stem.starts_with("keep-"));

    const rule::FixEngineResult fixed = FixTyping(text, kind, stage);
    fs::path out_path = c.input;
    out_path.replace_extension(".out" + ext);
    EXPECT_TRUE(MatchesGolden(fixed.text, out_path));
    EXPECT_TRUE(fixed.converged);
    if (stem.starts_with("unfixable-")) continue;
    bool accepted = false;
    const validate::ValidationResult result = Compile(fixed.text, kind, stage, &accepted);
    EXPECT_TRUE(accepted) << fixed.text << Messages(result);
    EXPECT_EQ(FixTyping(fixed.text, kind, stage).text, fixed.text) << "fixing twice changed it";
  }
}

}  // namespace
}  // namespace shaderport::typing_test
