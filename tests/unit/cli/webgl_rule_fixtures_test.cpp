// A fixture per browser check: tests/rules/webgl-checks/<name>.frag|vert is a small
// shader for which Chromium reports what webgl/<name> names, and `check` must report
// that id, and give Chromium's verdict (chromium-verdicts.json, recorded with
// tools/browser/record_verdicts.py or browser_compile.BrowserCompiler: 31 rejected;
// extension-placement is a warning in WebGL 1, as in Chromium). Every webgl/* id of the
// catalog has one; the program checks (link/*) have a program in tests/rules/link-checks/.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <string_view>

#include "cli/cli_test_util.h"
#include "diag/rule_catalog.h"

namespace shaderport::testing {
namespace {

// `check --format json` over a fixture folder, and the Chromium verdicts recorded there.
struct FixtureRun {
  int exit_code = 0;
  std::string err;
  nlohmann::json check;
  nlohmann::json chromium;
};

FixtureRun CheckFixtures(const std::filesystem::path& dir) {
  const CommandResult result = RunShaderport("check --format json --no-config --no-cache .", dir);
  FixtureRun run{result.exit_code, result.err, {}, {}};
  if (result.exit_code == 1) run.check = nlohmann::json::parse(result.out);
  std::ifstream recorded(dir / "chromium-verdicts.json");
  run.chromium = nlohmann::json::parse(recorded);
  return run;
}

TEST(WebglRuleFixtures, EachFixtureGetsItsRule) {
  const std::filesystem::path dir = SourceDir() / "tests" / "rules" / "webgl-checks";
  const FixtureRun run = CheckFixtures(dir);
  ASSERT_EQ(run.exit_code, 1) << run.err;
  const nlohmann::json& json = run.check;
  const nlohmann::json& chromium = run.chromium;
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
  EXPECT_GE(fixtures, 32u);
}

// The program checks: tests/rules/link-checks/<name>.vert + <name>.frag, a program
// Chromium compiles or links as its chromium-verdicts.json records
// (browser_compile.BrowserCompiler.link). `check` links same-stem pairs: one of the two
// files must get link/<name>, and an error exactly when Chromium fails the program.
TEST(WebglRuleFixtures, EachProgramGetsItsRule) {
  const std::filesystem::path dir = SourceDir() / "tests" / "rules" / "link-checks";
  const FixtureRun run = CheckFixtures(dir);
  ASSERT_EQ(run.exit_code, 1) << run.err;
  const nlohmann::json& json = run.check;
  const nlohmann::json& chromium = run.chromium;
  std::map<std::string, std::set<std::string>> rules;
  std::map<std::string, bool> errors;
  for (const auto& file : json["files"]) {
    const std::string path = file["path"];
    const std::string stem = path.substr(0, path.rfind('.'));
    for (const auto& diagnostic : file["diagnostics"]) {
      rules[stem].insert(diagnostic["rule"]);
      errors[stem] = errors[stem] || diagnostic["severity"] == "error";
    }
  }
  size_t programs = 0;
  for (const auto& [name, verdict] : chromium.items()) {
    if (name.starts_with("_")) continue;
    EXPECT_TRUE(rules[name].contains("link/" + name)) << name;
    const bool fails = !verdict["vertex_compiled"].get<bool>() ||
                       !verdict["fragment_compiled"].get<bool>() || !verdict["linked"].get<bool>();
    EXPECT_EQ(errors[name], fails) << name;
    ++programs;
  }
  EXPECT_EQ(programs, 6u);
}

// Every webgl/* id of the catalog has a fixture shader, every link/* id a program.
TEST(WebglRuleFixtures, EveryBrowserCheckHasOne) {
  const std::filesystem::path rules = SourceDir() / "tests" / "rules";
  for (const RuleDescription& rule : RuleCatalog()) {
    const std::string id(rule.id);
    const std::string name = id.substr(id.find('/') + 1);
    if (id.starts_with("webgl/")) {
      EXPECT_TRUE(std::filesystem::exists(rules / "webgl-checks" / (name + ".frag")) ||
                  std::filesystem::exists(rules / "webgl-checks" / (name + ".vert")))
          << id << " has no fixture in tests/rules/webgl-checks/";
    } else if (id.starts_with("link/")) {
      EXPECT_TRUE(std::filesystem::exists(rules / "link-checks" / (name + ".frag")))
          << id << " has no program in tests/rules/link-checks/";
    }
  }
}

}  // namespace
}  // namespace shaderport::testing
