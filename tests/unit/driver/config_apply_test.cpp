#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "driver/config/config.h"
#include "driver/config/find_config.h"

namespace shaderport::driver {
namespace {

Diagnostic Make(std::string rule, Severity severity = Severity::kError) {
  Diagnostic d;
  d.rule_id = std::move(rule);
  d.severity = severity;
  return d;
}

TEST(ConfigApply, MostSpecificPatternWins) {
  Config config;
  config.rules = {{"glslang/missing-precision", RuleLevel::kWarning},
                  {"glslang/*", RuleLevel::kOff},
                  {"*", RuleLevel::kNote}};
  EXPECT_EQ(RuleLevelFor(config, "glslang/missing-precision"), RuleLevel::kWarning);
  EXPECT_EQ(RuleLevelFor(config, "glslang/other"), RuleLevel::kOff);
  EXPECT_EQ(RuleLevelFor(config, "input/empty"), RuleLevel::kNote);
  config.rules.push_back({"glslang/*", RuleLevel::kError});  // later equal one wins
  EXPECT_EQ(RuleLevelFor(config, "glslang/other"), RuleLevel::kError);
  EXPECT_FALSE(RuleLevelFor(Config{}, "input/empty").has_value());
}

TEST(ConfigApply, OffDropsAndLevelsOverride) {
  Config config;
  config.rules = {{"suppression/*", RuleLevel::kOff}, {"input/empty", RuleLevel::kWarning}};
  DiagnosticList list = {Make("suppression/unused", Severity::kWarning), Make("input/empty"),
                         Make("input/binary")};
  ApplyRuleConfig(config, list);
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0].rule_id, "input/empty");
  EXPECT_EQ(list[0].severity, Severity::kWarning);
  EXPECT_EQ(list[1].severity, Severity::kError);
}

TEST(ConfigApply, FailOnThreshold) {
  Config config;
  const DiagnosticList warnings = {Make("a/b", Severity::kWarning)};
  EXPECT_FALSE(FailsCheck(config, warnings));
  config.fail_on = Severity::kWarning;
  EXPECT_TRUE(FailsCheck(config, warnings));
  EXPECT_FALSE(FailsCheck(config, {Make("a/b", Severity::kNote)}));
  EXPECT_FALSE(FailsCheck(config, {}));
}

TEST(ConfigApply, IncludeExcludeAndOverridesAreRelativeToTheConfig) {
  Config config;
  config.directory = "/proj";
  config.include = {"shaders/**"};
  config.exclude = {"shaders/third_party/**", "**/*.gen.glsl"};
  config.files = {
      {"shaders/toy/**", Dialect::kShaderToy, std::nullopt, std::nullopt},
      {"shaders/toy/*.vert", std::nullopt, model::Stage::kVertex, model::Target::kWebGL2}};
  EXPECT_TRUE(IsIncluded(config, "/proj/shaders/a.frag"));
  EXPECT_TRUE(IsIncluded(config, "/proj/shaders/./sub/../a.frag"));
  EXPECT_FALSE(IsIncluded(config, "/proj/other/a.frag"));
  EXPECT_FALSE(IsIncluded(config, "/proj/shaders/third_party/x.frag"));
  EXPECT_FALSE(IsIncluded(config, "/proj/shaders/deep/x.gen.glsl"));
  EXPECT_FALSE(IsIncluded(config, "/elsewhere/shaders/a.frag"));
  EXPECT_EQ(PathInConfig(config, "/proj/shaders/a.frag"), "shaders/a.frag");
  EXPECT_FALSE(PathInConfig(config, "/other/a.frag").has_value());

  const FileSettings vert = SettingsFor(config, "/proj/shaders/toy/q.vert");
  EXPECT_EQ(vert.dialect, Dialect::kShaderToy);
  EXPECT_EQ(vert.stage, model::Stage::kVertex);
  EXPECT_EQ(vert.target, model::Target::kWebGL2);  // a later [[files]] entry adds the target
  const FileSettings frag = SettingsFor(config, "/proj/shaders/toy/q.frag");
  EXPECT_FALSE(frag.stage.has_value());
  EXPECT_FALSE(frag.target.has_value());
  EXPECT_FALSE(SettingsFor(config, "/proj/web/q.frag").dialect.has_value());
}

class ConfigFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = std::filesystem::temp_directory_path() /
            ("shaderport-config-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(root_ / "a" / "b" / "c");
  }
  void TearDown() override { std::filesystem::remove_all(root_); }
  void Write(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
  }
  std::filesystem::path root_;
};

TEST_F(ConfigFiles, FindConfigWalksUpToTheNearest) {
  Write(root_ / "a" / ".shaderport.toml", "[check]\nfail-on = \"note\"\n");
  Write(root_ / "a" / "b" / "c" / "x.frag", "void main() {}\n");
  EXPECT_EQ(FindConfigFor(root_ / "a" / "b" / "c" / "x.frag"), root_ / "a" / ".shaderport.toml");
  EXPECT_EQ(FindConfigFor(root_ / "a" / "b"), root_ / "a" / ".shaderport.toml");
  Write(root_ / "a" / "b" / ".shaderport.toml", "");
  EXPECT_EQ(FindConfigFor(root_ / "a" / "b" / "c" / "x.frag"),
            root_ / "a" / "b" / ".shaderport.toml");

  SourceManager sources;
  const ConfigResult loaded = LoadConfig(root_ / "a" / ".shaderport.toml", sources);
  EXPECT_TRUE(loaded.diagnostics.empty());
  EXPECT_EQ(loaded.config.fail_on, Severity::kNote);
  EXPECT_EQ(loaded.config.directory, root_ / "a");
}

TEST_F(ConfigFiles, LoadReportsMissingAndHugeFiles) {
  SourceManager sources;
  ConfigResult missing = LoadConfig(root_ / "nope.toml", sources);
  ASSERT_EQ(missing.diagnostics.size(), 1u);
  EXPECT_EQ(missing.diagnostics[0].rule_id, "config/syntax-error");
  Write(root_ / "big.toml", std::string(kMaxConfigBytes + 1, '#'));
  EXPECT_EQ(LoadConfig(root_ / "big.toml", sources).diagnostics.size(), 1u);
}

}  // namespace
}  // namespace shaderport::driver
