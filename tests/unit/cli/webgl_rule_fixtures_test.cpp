// A fixture per browser check: tests/rules/webgl-checks/<name>.frag|vert is the
// smallest shader that Chromium rejects for the reason webgl/<name> names, and
// `check` must report that id for it (the verdicts themselves are compared with
// Chromium's in tests/browser-verdicts and the conformance tests).
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
  size_t fixtures = 0;
  for (const auto& file : json["files"]) {
    const std::string path = file["path"];
    const std::string wanted = "webgl/" + path.substr(0, path.rfind('.'));
    std::set<std::string> rules;
    for (const auto& diagnostic : file["diagnostics"]) rules.insert(diagnostic["rule"]);
    EXPECT_TRUE(rules.contains(wanted)) << path << " does not get " << wanted;
    ++fixtures;
  }
  EXPECT_GE(fixtures, 17u);
}

}  // namespace
}  // namespace shaderport::testing
