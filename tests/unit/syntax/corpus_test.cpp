// Sweeps over the shared corpora: valid shaders parse without syntax errors
// and every tree is well formed.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "parse_helpers.h"

namespace shaderport::glsl::testing {
namespace {

std::string FirstError(const Parsed& parsed) {
  for (const auto& d : parsed.result.diagnostics) {
    if (d.severity != Severity::kError) continue;
    LineColumn at = parsed.sources.Get(d.range.file).LocationOf(d.range.begin);
    return std::to_string(at.line) + ":" + std::to_string(at.column) + ": " + d.message + " [" +
           d.rule_id + "]";
  }
  return "";
}

TEST(CorpusTest, ConformanceStagesExpectedToCompileHaveNoSyntaxErrors) {
  std::ifstream in(std::string(SHADERPORT_SHARED_DIR) + "/conformance/webgl-cts.jsonl");
  ASSERT_TRUE(in.good());
  int stages = 0, clean = 0, shape_problems = 0;
  std::string line;
  while (std::getline(in, line)) {
    auto c = nlohmann::json::parse(line);
    for (const char* stage : {"vertex", "fragment"}) {
      bool vertex = std::string(stage) == "vertex";
      const auto& ok = c["expected"][vertex ? "vShaderSuccess" : "fShaderSuccess"];
      if (!ok.is_boolean() || !ok.get<bool>() || !c[stage].is_string()) continue;
      auto parsed = ParseText(c[stage].get<std::string>(), 100);
      ++stages;
      bool has_syntax_error = false;
      for (const auto& d : parsed->result.diagnostics) {
        if (d.severity == Severity::kError) has_syntax_error = true;
      }
      if (!has_syntax_error) {
        ++clean;
      } else {
        ADD_FAILURE() << c["id"] << " " << stage << ": " << FirstError(*parsed);
      }
      auto problems = CheckTreeShape(*parsed);
      if (!problems.empty()) {
        ++shape_problems;
        ADD_FAILURE() << c["id"] << " " << stage << ": " << problems.front();
      }
    }
  }
  EXPECT_EQ(stages, 3693);
  EXPECT_EQ(clean, stages);
  EXPECT_EQ(shape_problems, 0);
}

TEST(CorpusTest, ShaderToyPassesHaveNoSyntaxErrors) {
  std::ifstream in(std::string(SHADERPORT_SHARED_DIR) + "/corpus-shadertoy/permissive.jsonl");
  ASSERT_TRUE(in.good());
  int passes = 0, clean = 0, shape_problems = 0;
  std::string line;
  while (std::getline(in, line)) {
    auto shader = nlohmann::json::parse(line);
    std::string common;
    for (const auto& pass : shader["passes"]) {
      if (pass["type"] == "common") common = pass["code"].get<std::string>();
    }
    for (const auto& pass : shader["passes"]) {
      if (pass["type"] == "common") continue;
      std::vector<std::string> texts;
      if (!common.empty()) texts.push_back(common);
      texts.push_back(pass["code"].get<std::string>());
      auto parsed = ParseFiles(texts, 300);
      ++passes;
      if (!HasErrors(parsed->result.diagnostics)) {
        ++clean;
      } else {
        ADD_FAILURE() << shader["id"] << " " << pass["name"] << ": " << FirstError(*parsed);
      }
      auto problems = CheckTreeShape(*parsed);
      if (!problems.empty()) {
        ++shape_problems;
        ADD_FAILURE() << shader["id"] << " " << pass["name"] << ": " << problems.front();
      }
    }
  }
  EXPECT_EQ(passes, 1155);
  EXPECT_EQ(clean, passes);
  EXPECT_EQ(shape_problems, 0);
}

}  // namespace
}  // namespace shaderport::glsl::testing
