// check marks what `shaderport fix` repairs: glslang's errors that a rule repairs
// carry that rule's fix-it ([*] in text, "fixable" in JSON, fixes in SARIF), and the
// summary counts them; an error that fix leaves is not marked.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_test_util.h"
#include "cli/temp_project.h"

namespace shaderport::testing {
namespace {

constexpr const char* kRepairable =
    "void mainImage(out vec4 fragColor, in vec2 fragCoord)\n"
    "{\n"
    "    float t = iGlobalTime * 1;\n"
    "    vec3 c = 0.5;\n"
    "    fragColor = vec4(c * t, 1.0);\n"
    "}\n";

// One repairable error and one that no rule repairs (an undeclared name).
constexpr const char* kMixed =
    "void mainImage(out vec4 fragColor, in vec2 fragCoord)\n"
    "{\n"
    "    float t = iGlobalTime;\n"
    "    fragColor = vec4(nothing);\n"
    "}\n";

TEST(FixableCli, TextMarksRepairedErrorsAndCountsThem) {
  TempProject project("fixable-text");
  project.Write("a.glsl", kRepairable);
  const CommandResult result = RunShaderport("check a.glsl", project.Root());
  EXPECT_EQ(result.exit_code, 1) << result.out << result.err;
  EXPECT_NE(result.out.find("a.glsl:3:15: error: [*] 'iGlobalTime': undeclared identifier"),
            std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("fix-it: replace 'iGlobalTime' with 'iTime'"), std::string::npos);
  EXPECT_NE(result.out.find("fix-it: replace '1' with '1.0'"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("\n[*] 3 fixable with 'shaderport fix'\n"), std::string::npos)
      << result.out;
}

TEST(FixableCli, AFindingThatFixLeavesIsNotMarked) {
  TempProject project("fixable-mixed");
  project.Write("a.glsl", kMixed);
  const CommandResult result = RunShaderport("check --format json a.glsl", project.Root());
  ASSERT_EQ(result.exit_code, 1) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  int marked = 0;
  for (const auto& diagnostic : json["files"][0]["diagnostics"]) {
    const bool fixable = diagnostic["fixable"].get<bool>();
    const std::string message = diagnostic["message"];
    EXPECT_EQ(fixable, message.find("iGlobalTime") != std::string::npos) << message;
    EXPECT_EQ(fixable, !diagnostic["fixes"].empty()) << message;
    marked += fixable ? 1 : 0;
  }
  EXPECT_EQ(marked, 1);
  EXPECT_EQ(json["summary"]["fixable"], 1);
  const CommandResult text = RunShaderport("check a.glsl", project.Root());
  EXPECT_NE(text.out.find("[*] 1 fixable with 'shaderport fix'"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("error: 'nothing': undeclared identifier"), std::string::npos)
      << text.out;
}

TEST(FixableCli, SarifCarriesTheRepairAsAFix) {
  TempProject project("fixable-sarif");
  project.Write("a.glsl", kRepairable);
  const CommandResult result = RunShaderport("check --format sarif a.glsl", project.Root());
  const auto sarif = nlohmann::json::parse(result.out);
  int with_fixes = 0;
  for (const auto& item : sarif["runs"][0]["results"]) {
    if (item.contains("fixes")) ++with_fixes;
  }
  EXPECT_EQ(with_fixes, 3) << result.out;
}

TEST(FixableCli, ApplyingTheMarkedFixesGivesWhatFixWrites) {
  // The JSON fix-its, applied from the end backwards, give fix's own output.
  TempProject project("fixable-apply");
  project.Write("a.glsl", kRepairable);
  const auto json =
      nlohmann::json::parse(RunShaderport("check --format json a.glsl", project.Root()).out);
  std::vector<std::pair<size_t, std::pair<size_t, std::string>>> edits;
  for (const auto& diagnostic : json["files"][0]["diagnostics"]) {
    for (const auto& fix : diagnostic["fixes"]) {
      const auto& range = fix["location"]["range"];
      edits.push_back({range["start"]["offset"].get<size_t>(),
                       {range["end"]["offset"].get<size_t>(), fix["replacement"]}});
    }
  }
  std::sort(edits.rbegin(), edits.rend());
  std::string text = kRepairable;
  for (const auto& [begin, rest] : edits) text.replace(begin, rest.first - begin, rest.second);
  const CommandResult fixed = RunShaderport("fix a.glsl", project.Root());
  EXPECT_EQ(text, fixed.out);
}

}  // namespace
}  // namespace shaderport::testing
