// `--emit reflect` goldens (tests/golden/toolchain/reflect/, regenerate with
// SHADERPORT_UPDATE_GOLDENS=1), each output also checked against docs/reflect.schema.json.
#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "emit_test_util.h"
#include "golden.h"
#include "json_schema_subset.h"

namespace shaderport::toolchain {
namespace {

using testing::CompilingCorpusShaders;
using testing::CorpusShader;
using testing::EmitText;
using testing::OptionsFor;
using testing::ReadText;
using testing::RuleIds;
using testing::WriteText;
namespace fs = std::filesystem;

const fs::path kData = fs::path(SHADERPORT_SOURCE_DIR) / "tests/unit/toolchain/data/reflect";
const fs::path kGolden = fs::path(SHADERPORT_SOURCE_DIR) / "tests/golden/toolchain/reflect";

nlohmann::json Schema() {
  return nlohmann::json::parse(
      ReadText(fs::path(SHADERPORT_SOURCE_DIR) / "docs/reflect.schema.json"));
}

std::string ReflectJson(const std::string& text, model::Stage stage, bool shadertoy,
                        const std::string& name) {
  EmitOptions options = OptionsFor(EmitKind::kReflect);
  options.shadertoy = shadertoy;
  const EmitResult result = EmitText(text, stage, options, name);
  EXPECT_TRUE(result.diagnostics.empty()) << RuleIds(result.diagnostics);
  EXPECT_FALSE(result.binary);
  return result.output;
}

void CheckGolden(const std::string& golden_name, const std::string& json) {
  SCOPED_TRACE(golden_name);
  ASSERT_FALSE(json.empty());
  const std::vector<std::string> errors =
      testing::SchemaErrors(Schema(), nlohmann::json::parse(json));
  EXPECT_TRUE(errors.empty()) << errors.front();
  const fs::path golden = kGolden / (golden_name + ".json");
  EXPECT_TRUE(shaderport::testing::MatchesGolden(json, golden));
}

TEST(ReflectGolden, HandWrittenShaders) {
  const struct {
    const char* file;
    model::Stage stage;
    bool shadertoy;
  } cases[] = {{"shadertoy-channels.frag", model::Stage::kFragment, true},
               {"resources.frag", model::Stage::kFragment, false},
               {"points.vert", model::Stage::kVertex, false}};
  for (const auto& c : cases) {
    const std::string text = ReadText(kData / c.file);
    ASSERT_FALSE(text.empty()) << c.file;
    CheckGolden(fs::path(c.file).stem().string(), ReflectJson(text, c.stage, c.shadertoy, c.file));
  }
}

TEST(ReflectGolden, CorpusShaders) {
  int checked = 0;
  for (const CorpusShader& shader : CompilingCorpusShaders()) {
    if (shader.path != "ao/template.glsl" && shader.path != "raymarch/stage4-shadows.glsl" &&
        shader.path != "ssao/geometry.vert" && shader.path != "ssao/ssao.frag") {
      continue;
    }
    std::string name = "corpus-" + shader.path;
    for (char& c : name) {
      if (c == '/') c = '-';
    }
    CheckGolden(name, ReflectJson(shader.webgl2, shader.stage, shader.shadertoy, shader.path));
    ++checked;
  }
  EXPECT_EQ(checked, 4);
}

// Every corpus shader's reflection fits the schema, and names its entry point.
TEST(ReflectGolden, EveryCorpusShaderFitsTheSchema) {
  const nlohmann::json schema = Schema();
  for (const CorpusShader& shader : CompilingCorpusShaders()) {
    SCOPED_TRACE(shader.path);
    const nlohmann::json json = nlohmann::json::parse(
        ReflectJson(shader.webgl2, shader.stage, shader.shadertoy, shader.path));
    const std::vector<std::string> errors = testing::SchemaErrors(schema, json);
    EXPECT_TRUE(errors.empty()) << errors.front();
    EXPECT_EQ(json["entryPoint"], "main");
    EXPECT_EQ(json.contains("shadertoy"), shader.shadertoy);
  }
}

// The facts the goldens hold, asserted directly so a wrong golden cannot hide them.
TEST(ReflectGolden, ShaderToyChannelUsage) {
  const nlohmann::json json = nlohmann::json::parse(ReflectJson(
      ReadText(kData / "shadertoy-channels.frag"), model::Stage::kFragment, true, "channels.frag"));
  const nlohmann::json& channels = json["shadertoy"]["channels"];
  ASSERT_EQ(channels.size(), 4u);
  EXPECT_EQ(channels[0]["kind"], "2D");
  EXPECT_EQ(channels[0]["functions"], nlohmann::json({"texelFetch"}));
  EXPECT_EQ(channels[1]["kind"], "Cube");
  EXPECT_EQ(channels[1]["functions"], nlohmann::json({"textureLod"}));  // via a helper function
  EXPECT_EQ(channels[2]["kind"], "3D");
  EXPECT_EQ(channels[2]["functions"], nlohmann::json({"texture"}));
  EXPECT_TRUE(channels[2]["used"].get<bool>());
  EXPECT_FALSE(channels[3]["used"].get<bool>());
  EXPECT_EQ(json["shadertoy"]["uniformsUsed"], nlohmann::json({"iResolution", "iTime", "iMouse"}));
  EXPECT_EQ(json["builtinInputs"], nlohmann::json({"gl_FragCoord"}));
}

}  // namespace
}  // namespace shaderport::toolchain
