// A fixture per browser check: tests/rules/webgl-checks/<name>.frag|vert is a small
// shader for which Chromium reports what webgl/<name> names, and `check` must report
// that id, and give Chromium's verdict (chromium-verdicts.json, recorded with
// tools/browser/record_verdicts.py or browser_compile.BrowserCompiler: 30 rejected;
// extension-placement is a warning in WebGL 1, as in Chromium). Every webgl/* id of the
// catalog has one, but the program checks, which need two stages linked.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <string_view>

#include "cli/cli_test_util.h"
#include "diag/rule_catalog.h"

namespace shaderport::testing {
namespace {

TEST(WebglRuleFixtures, EachFixtureGetsItsRule) {
  const std::filesystem::path dir = SourceDir() / "tests" / "rules" / "webgl-checks";
  const CommandResult result = RunShaderport("check --format json --no-config --no-cache .", dir);
  ASSERT_EQ(result.exit_code, 1) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  std::ifstream recorded(dir / "chromium-verdicts.json");
  const auto chromium = nlohmann::json::parse(recorded);
  size_t fixtures = 0;
  for (const auto& file : json["files"]) {
    const std::string path = file["path"];
    const std::string wanted = "webgl/" + path.substr(0, path.rfind('.'));
    std::set<std::string> rules;
    bool error = false;
    for (const auto& diagnostic : file["diagnostics"]) {
      rules.insert(diagnostic["rule"]);
      error = error || diagnostic["severity"] == "error";
    }
    EXPECT_TRUE(rules.contains(wanted)) << path << " does not get " << wanted;
    ASSERT_TRUE(chromium.contains(path)) << path << " has no recorded Chromium verdict";
    EXPECT_EQ(error, !chromium[path]["compiled"].get<bool>()) << path;
    ++fixtures;
  }
  EXPECT_GE(fixtures, 31u);
}

// The program checks run on two linked stages (ProgramLink.*, the conformance suites).
TEST(WebglRuleFixtures, EveryBrowserCheckHasOne) {
  const std::filesystem::path dir = SourceDir() / "tests" / "rules" / "webgl-checks";
  const std::set<std::string_view> program_checks = {
      "webgl/link-invariant", "webgl/link-uniform", "webgl/link-uniform-vectors",
      "webgl/link-varying",   "webgl/link-version", "webgl/varying-packing"};
  for (const RuleDescription& rule : RuleCatalog()) {
    if (!rule.id.starts_with("webgl/") || program_checks.contains(rule.id)) continue;
    const std::string stem(rule.id.substr(6));
    EXPECT_TRUE(std::filesystem::exists(dir / (stem + ".frag")) ||
                std::filesystem::exists(dir / (stem + ".vert")))
        << rule.id << " has no fixture in tests/rules/webgl-checks/";
  }
}

}  // namespace
}  // namespace shaderport::testing
