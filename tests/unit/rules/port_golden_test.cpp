// Golden cases of the port/* rules (webgl2/* before the rename), under tests/rules/port-<rule>/:
//   <case>.frag|.vert        the input (GLSL ES 1.00 unless it says otherwise)
//   <case>.diag              what the rule alone reports, with its fix-its
//   <case>.out.frag|.vert    the input ported by every webgl2/* rule (fix engine)
// Every output must compile as GLSL ES 3.00 with glslang, and porting it again
// must change nothing. Cases named keep-* expect no finding from the rule;
// unfixable-* cases are not expected to compile. SHADERPORT_UPDATE_GOLDENS=1
// rewrites the expected files.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "finding_format.h"
#include "golden.h"
#include "port_test_support.h"
#include "rules/golden_cases.h"
#include "rules/registry.h"

namespace shaderport::port_test {
namespace {

using shaderport::testing::FormatFindings;
using shaderport::testing::MatchesGolden;
using shaderport::testing::ReadWholeFile;

namespace fs = std::filesystem;

using Case = testing::GoldenCase;

std::vector<Case> AllCases() { return testing::GoldenCases("port"); }

TEST(PortGolden, EveryRuleHasCases) {
  const auto cases = AllCases();
  for (const rule::Rule* r : PortRules()) {
    int count = 0;
    for (const Case& c : cases) count += c.rule_id == r->Info().id;
    EXPECT_GE(count, 2) << r->Info().id << " needs golden cases";
  }
  EXPECT_EQ(PortRules().size(), 7u);
}

TEST(PortGolden, Cases) {
  const auto cases = AllCases();
  ASSERT_GE(cases.size(), 20u);
  for (const Case& c : cases) {
    SCOPED_TRACE(c.input.string());
    const rule::Rule* r = rules::FindRule(c.rule_id);
    ASSERT_NE(r, nullptr) << c.rule_id;
    const std::string text = ReadWholeFile(c.input);
    const std::string stem = c.input.stem().string();
    const std::string ext = c.input.extension().string();
    const auto stage = ext == ".vert" ? model::Stage::kVertex : model::Stage::kFragment;
    const int version = text.find("#version 300 es") == std::string::npos ? 100 : 300;

    const RuleRun run = RunOneRule(*r, text, stage, rule::PortMode::kPort, version);
    if (stem.starts_with("keep-")) {
      EXPECT_TRUE(run.diagnostics.empty())
          << shaderport::testing::FormatFindings(text, run.diagnostics);
    } else {
      EXPECT_FALSE(run.diagnostics.empty());
    }
    for (const Diagnostic& d : run.diagnostics) EXPECT_EQ(d.rule_id, c.rule_id);
    EXPECT_TRUE(MatchesGolden(shaderport::testing::FormatFindings(text, run.diagnostics),
                              c.input.parent_path() / (stem + ".diag")));

    const rule::FixEngineResult ported = PortWithPortRules(text, stage, version);
    EXPECT_TRUE(ported.converged);
    EXPECT_TRUE(MatchesGolden(ported.text, c.input.parent_path() / (stem + ".out" + ext)));
    if (!stem.starts_with("unfixable-")) {
      EXPECT_TRUE(ported.text.starts_with("#version 300 es\n")) << ported.text;
      const auto compiled = Compile(ported.text, stage);
      EXPECT_TRUE(compiled.Accepted(false))
          << ported.text << "\n"
          << Messages(compiled) << "remaining:\n"
          << shaderport::testing::FormatFindings(text, ported.remaining) << "front end:\n"
          << shaderport::testing::FormatFindings(text, ported.front_end);
      const rule::FixEngineResult again = PortWithPortRules(ported.text, stage, 300);
      EXPECT_EQ(again.text, ported.text) << "porting twice changed the text";
    }
  }
}

}  // namespace
}  // namespace shaderport::port_test
