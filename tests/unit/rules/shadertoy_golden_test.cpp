// Golden cases of the harness rules, under tests/rules/:
//   shadertoy-<rule>/<case>.glsl   input, checked against shadertoy/<rule> alone
//   dialect-<name>/<case>.glsl     input, checked against every shadertoy/* rule
//   <case>.diag                    what the rule(s) report during the port
//   <case>.out.frag                the input ported by every registered rule
// A first-lines comment `// dialect: NAME` picks the dialect (default shadertoy),
// `// channel: N=2d|cube|3d` a channel type. Every output must compile as GLSL ES
// 3.00 with glslang (unfixable-* ones must not), and porting it again must change
// nothing. keep-* cases expect no finding of their rule. The .diag files list every
// shadertoy/* finding. SHADERPORT_UPDATE_GOLDENS=1 rewrites the expected files.
#include <gtest/gtest.h>

#include <regex>

#include "shadertoy_test_support.h"

namespace shaderport::shadertoy_test {
namespace {

namespace fs = std::filesystem;

struct Case {
  fs::path input;
  std::string rule_prefix;  // "shadertoy/uniforms" or "shadertoy/" for every harness rule
};

std::vector<Case> AllCases() {
  std::vector<Case> cases;
  const fs::path root = fs::path(SHADERPORT_SOURCE_DIR) / "tests" / "rules";
  for (const auto& dir : fs::directory_iterator(root)) {
    const std::string name = dir.path().filename().string();
    std::string prefix;
    if (name.starts_with("shadertoy-")) prefix = "shadertoy/" + name.substr(10);
    if (name.starts_with("dialect-")) prefix = "shadertoy/";
    if (prefix.empty() || !dir.is_directory()) continue;
    for (const auto& file : fs::directory_iterator(dir.path())) {
      if (file.path().extension() == ".glsl") cases.push_back({file.path(), prefix});
    }
  }
  std::sort(cases.begin(), cases.end(),
            [](const Case& a, const Case& b) { return a.input < b.input; });
  return cases;
}

rule::PortSettings CaseSettings(const std::string& text) {
  std::smatch match;
  std::string dialect = "shadertoy";
  if (std::regex_search(text, match, std::regex("// dialect: ([a-z-]+)"))) dialect = match[1];
  rule::PortSettings settings = HarnessSettings(model::FindBuiltinDialect(dialect));
  if (std::regex_search(text, match, std::regex("// channel: ([0-3])=(2d|cube|3d)"))) {
    const std::string kind = match[2];
    settings.channels[std::stoi(match[1])] = kind == "2d"     ? model::ChannelKind::k2D
                                             : kind == "cube" ? model::ChannelKind::kCube
                                                              : model::ChannelKind::k3D;
  }
  return settings;
}

TEST(ShadertoyGolden, CasesExist) { EXPECT_GE(AllCases().size(), 15u); }

TEST(ShadertoyGolden, EveryCase) {
  for (const Case& c : AllCases()) {
    SCOPED_TRACE(c.input.string());
    const std::string text = shaderport::testing::ReadWholeFile(c.input);
    const rule::PortSettings settings = CaseSettings(text);
    ASSERT_NE(settings.harness, nullptr);

    // What the rule(s) found over the whole port (located in the input), since
    // some wait for another rule's fix (shadertoy/uniforms for the #version).
    const rule::FixEngineResult ported = Port(text, settings);
    EXPECT_TRUE(ported.converged);
    DiagnosticList found;
    for (const DiagnosticList* list : {&ported.fixed, &ported.remaining}) {
      for (const Diagnostic& d : *list) {
        if (d.rule_id.starts_with("shadertoy/")) found.push_back(d);
      }
    }
    std::stable_sort(found.begin(), found.end(), [](const Diagnostic& a, const Diagnostic& b) {
      return a.range.begin < b.range.begin;
    });
    const std::string stem = c.input.stem().string();
    const bool rule_found = std::any_of(found.begin(), found.end(), [&](const Diagnostic& d) {
      return d.rule_id.starts_with(c.rule_prefix);
    });
    EXPECT_EQ(rule_found, !stem.starts_with("keep-"))
        << shaderport::testing::FormatFindings(text, found);
    EXPECT_TRUE(shaderport::testing::MatchesGolden(shaderport::testing::FormatFindings(text, found),
                                                   c.input.parent_path() / (stem + ".diag")));
    EXPECT_TRUE(shaderport::testing::MatchesGolden(ported.text,
                                                   c.input.parent_path() / (stem + ".out.frag")));
    const auto compiled = CompileEssl300(ported.text);
    EXPECT_EQ(compiled.Accepted(true), !stem.starts_with("unfixable-"))
        << Messages(compiled) << ported.text;

    const rule::FixEngineResult again = Port(ported.text, settings);
    EXPECT_EQ(again.text, ported.text) << "porting twice changed the text";
  }
}

}  // namespace
}  // namespace shaderport::shadertoy_test
