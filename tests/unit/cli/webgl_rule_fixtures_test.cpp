// A fixture per browser check: tests/rules/webgl-checks/<name>.frag|vert is a small
// shader for which Chromium reports what webgl/<name> names, and `check` must report
// that id, and give Chromium's verdict (chromium-verdicts.json, recorded with
// tools/browser/record_verdicts.py: 17 rejected; extension-placement is a warning in
// WebGL 1, as in Chromium).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "cli/cli_test_util.h"

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
  EXPECT_GE(fixtures, 17u);
}

}  // namespace
}  // namespace shaderport::testing
