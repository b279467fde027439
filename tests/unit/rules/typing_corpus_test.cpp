// The typing/* rules on real mistakes: the seed's strict-typing corpus (every
// broken case is fixed and then validates under its dialect's contract) and the
// WebGL conformance cases under conformance/glsl/implicit that must fail
// (glslang rejects each as written and accepts it after the fix).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "golden.h"
#include "typing_test_support.h"

namespace shaderport::typing_test {
namespace {

namespace fs = std::filesystem;

TEST(TypingCorpus, StrictTypingCasesAreFixed) {
  const fs::path root = fs::path(SHADERPORT_SOURCE_DIR) / "corpus";
  std::istringstream manifest(shaderport::testing::ReadWholeFile(root / "MANIFEST"));
  std::string line;
  int broken = 0;
  int fixed_count = 0;
  while (std::getline(manifest, line)) {
    if (!line.starts_with("strict-typing/")) continue;
    std::vector<std::string> fields;
    std::istringstream row(line);
    for (std::string field; std::getline(row, field, '\t');) fields.push_back(field);
    ASSERT_GE(fields.size(), 5u) << line;
    const Kind kind = fields[2] == "shadertoy" ? Kind::kShaderToy : Kind::kWebGL;
    const model::Stage stage =
        fields[3] == "vertex" ? model::Stage::kVertex : model::Stage::kFragment;
    const std::string text = shaderport::testing::ReadWholeFile(root / fields[0]);
    SCOPED_TRACE(fields[0]);
    bool accepted = false;
    Compile(text, kind, stage, &accepted);
    const rule::FixEngineResult fixed = FixTyping(text, kind, stage);
    if (fields[4] == "compiles") {
      EXPECT_TRUE(accepted);
      EXPECT_EQ(fixed.text, text) << "a control case was changed";
      continue;
    }
    ++broken;
    EXPECT_FALSE(accepted) << "expected glslang to reject the original";
    const validate::ValidationResult result = Compile(fixed.text, kind, stage, &accepted);
    EXPECT_TRUE(accepted) << fixed.text << Messages(result);
    EXPECT_FALSE(fixed.fixed.empty());
    fixed_count += accepted;
  }
  EXPECT_EQ(broken, 18);
  EXPECT_EQ(fixed_count, 18);
  std::cout << "strict-typing corpus: " << fixed_count << " of " << broken << " fixed\n";
}

TEST(TypingCorpus, ConformanceImplicitCasesAreFixed) {
  std::ifstream in(fs::path(SHADERPORT_SHARED_DIR) / "conformance" / "webgl-cts.jsonl");
  ASSERT_TRUE(in.good());
  int cases = 0;
  int fixed_count = 0;
  for (std::string line; std::getline(in, line);) {
    const nlohmann::json j = nlohmann::json::parse(line);
    if (j.value("folder", "") != "conformance/glsl/implicit") continue;
    const nlohmann::json& expected = j["expected"];
    const bool vertex_fails = !expected.value("vShaderSuccess", true);
    const bool fragment_fails = !expected.value("fShaderSuccess", true);
    if (!vertex_fails && !fragment_fails) continue;
    const model::Stage stage = vertex_fails ? model::Stage::kVertex : model::Stage::kFragment;
    const std::string text = j[vertex_fails ? "vertex" : "fragment"].get<std::string>();
    SCOPED_TRACE(j["id"].get<std::string>());
    ++cases;
    bool accepted = false;
    Compile(text, Kind::kWebGL, stage, &accepted);
    EXPECT_FALSE(accepted) << "glslang accepts the original";
    const rule::FixEngineResult fixed = FixTyping(text, Kind::kWebGL, stage);
    const validate::ValidationResult result = Compile(fixed.text, Kind::kWebGL, stage, &accepted);
    EXPECT_TRUE(accepted) << fixed.text << Messages(result);
    fixed_count += accepted;
  }
  EXPECT_EQ(cases, 37);
  EXPECT_EQ(fixed_count, cases);
  std::cout << "conformance/glsl/implicit: " << fixed_count << " of " << cases << " fixed\n";
}

}  // namespace
}  // namespace shaderport::typing_test
