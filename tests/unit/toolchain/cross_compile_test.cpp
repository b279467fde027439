// HLSL, MSL and the ESSL round trip through SPIRV-Cross, on every compiling corpus shader.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "emit_test_util.h"

namespace shaderport::toolchain {
namespace {

using testing::CompilingCorpusShaders;
using testing::CorpusShader;
using testing::EmitText;
using testing::GlslangErrors;
using testing::OptionsFor;
using testing::RuleIds;

// Names of the uniforms and samplers the shader actually uses, from --emit reflect.
std::vector<std::string> UsedUniforms(const CorpusShader& shader) {
  const EmitResult reflected =
      EmitText(shader.webgl2, shader.stage, OptionsFor(EmitKind::kReflect), shader.path);
  std::vector<std::string> names;
  if (HasErrors(reflected.diagnostics)) return names;
  const nlohmann::json json = nlohmann::json::parse(reflected.output);
  for (const char* list : {"uniforms", "samplers"}) {
    for (const auto& uniform : json[list]) {
      if (uniform["used"].get<bool>()) names.push_back(uniform["name"]);
    }
  }
  return names;
}

TEST(CrossCompile, HlslAndMslNameTheEntryPointAndEveryUsedUniform) {
  int uniforms_checked = 0;
  for (const CorpusShader& shader : CompilingCorpusShaders()) {
    SCOPED_TRACE(shader.path);
    const EmitResult hlsl =
        EmitText(shader.webgl2, shader.stage, OptionsFor(EmitKind::kHlsl), shader.path);
    const EmitResult msl =
        EmitText(shader.webgl2, shader.stage, OptionsFor(EmitKind::kMsl), shader.path);
    ASSERT_TRUE(hlsl.diagnostics.empty()) << RuleIds(hlsl.diagnostics);
    ASSERT_TRUE(msl.diagnostics.empty()) << RuleIds(msl.diagnostics);
    const char* stage_word = shader.stage == model::Stage::kVertex ? "vertex" : "fragment";
    // HLSL keeps SPIR-V's entry point name; MSL renames main (reserved in Metal) to main0.
    EXPECT_NE(hlsl.output.find(" main("), std::string::npos) << hlsl.output;
    EXPECT_NE(msl.output.find(std::string(stage_word) + " main0_out main0("), std::string::npos)
        << msl.output;
    for (const std::string& name : UsedUniforms(shader)) {
      EXPECT_NE(hlsl.output.find(name), std::string::npos) << "HLSL lacks " << name;
      EXPECT_NE(msl.output.find(name), std::string::npos) << "MSL lacks " << name;
      ++uniforms_checked;
    }
  }
  EXPECT_GE(uniforms_checked, 40);
}

TEST(CrossCompile, EsslRoundTripOfEveryCorpusShaderValidatesInGlslang) {
  int checked = 0;
  for (const CorpusShader& shader : CompilingCorpusShaders()) {
    for (const bool optimized : {false, true}) {
      SCOPED_TRACE(shader.path + (optimized ? " -O" : ""));
      EmitOptions options = OptionsFor(EmitKind::kEsslRoundtrip);
      if (optimized) options.optimize = "O";
      const EmitResult result = EmitText(shader.webgl2, shader.stage, options, shader.path);
      ASSERT_TRUE(result.diagnostics.empty()) << RuleIds(result.diagnostics);
      EXPECT_EQ(result.output.rfind("#version 300 es\n", 0), 0u) << result.output;
      EXPECT_EQ(GlslangErrors(result.output, shader.stage), "") << result.output;
      ++checked;
    }
  }
  EXPECT_GE(checked, 44);
}

// Unoptimised SPIR-V keeps the user's function and variable names in the round trip.
TEST(CrossCompile, UnoptimisedRoundTripIsReadable) {
  const std::string text =
      "#version 300 es\nprecision highp float;\nuniform float iTime;\nout vec4 color;\n"
      "float wave(float t) { return sin(t) * 0.5 + 0.5; }\n"
      "void main() { float brightness = wave(iTime); color = vec4(brightness); }\n";
  const EmitResult plain =
      EmitText(text, model::Stage::kFragment, OptionsFor(EmitKind::kEsslRoundtrip));
  ASSERT_TRUE(plain.diagnostics.empty()) << RuleIds(plain.diagnostics);
  EXPECT_NE(plain.output.find("float wave("), std::string::npos) << plain.output;
  EXPECT_NE(plain.output.find("uniform highp float iTime;"), std::string::npos) << plain.output;
  EXPECT_NE(plain.output.find("out highp vec4 color;"), std::string::npos) << plain.output;
  EmitOptions optimized = OptionsFor(EmitKind::kEsslRoundtrip);
  optimized.optimize = "O";
  const EmitResult inlined = EmitText(text, model::Stage::kFragment, optimized);
  ASSERT_TRUE(inlined.diagnostics.empty()) << RuleIds(inlined.diagnostics);
  EXPECT_EQ(inlined.output.find("float wave("), std::string::npos) << inlined.output;
  EXPECT_LT(inlined.words_after, inlined.words_before);
}

TEST(CrossCompile, ShaderModelAndMslVersionAreHonoured) {
  const std::string text =
      "#version 300 es\nprecision highp float;\nuniform sampler2D tex;\nin vec2 uv;\n"
      "out vec4 color;\nvoid main() { color = texture(tex, uv); }\n";
  EmitOptions sm30 = OptionsFor(EmitKind::kHlsl);
  sm30.hlsl_shader_model = 30;
  const EmitResult old_hlsl = EmitText(text, model::Stage::kFragment, sm30);
  const EmitResult new_hlsl = EmitText(text, model::Stage::kFragment, OptionsFor(EmitKind::kHlsl));
  ASSERT_TRUE(old_hlsl.diagnostics.empty()) << RuleIds(old_hlsl.diagnostics);
  ASSERT_TRUE(new_hlsl.diagnostics.empty()) << RuleIds(new_hlsl.diagnostics);
  EXPECT_NE(old_hlsl.output.find("sampler2D"), std::string::npos) << old_hlsl.output;
  EXPECT_NE(new_hlsl.output.find("Texture2D<float4> tex"), std::string::npos) << new_hlsl.output;

  EmitOptions msl1 = OptionsFor(EmitKind::kMsl);
  msl1.msl_version = 10200;
  const EmitResult old_msl = EmitText(text, model::Stage::kFragment, msl1);
  const EmitResult new_msl = EmitText(text, model::Stage::kFragment, OptionsFor(EmitKind::kMsl));
  ASSERT_TRUE(old_msl.diagnostics.empty()) << RuleIds(old_msl.diagnostics);
  EXPECT_NE(new_msl.output.find("texture2d<float> tex"), std::string::npos) << new_msl.output;
  EXPECT_NE(old_msl.output.find("main0"), std::string::npos);
}

}  // namespace
}  // namespace shaderport::toolchain
