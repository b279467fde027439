// The SPIR-V leg over the real ShaderToy corpus (shared/corpus-shadertoy/permissive.jsonl):
// every image pass that glslang accepts as WebGL2 either emits a valid module, HLSL, MSL and
// a round trip that glslang accepts again, or fails with a leg diagnostic, never as the user's
// error.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>

#include "emit_test_util.h"

namespace shaderport::toolchain {
namespace {

using testing::EmitText;
using testing::GlslangErrors;
using testing::OptionsFor;
using testing::ReadText;
using testing::RuleIds;
namespace fs = std::filesystem;

// The site's header with each channel's sampler type taken from the pass's inputs.
std::string Header(const nlohmann::json& inputs) {
  std::string samplers[4] = {"sampler2D", "sampler2D", "sampler2D", "sampler2D"};
  for (const auto& input : inputs) {
    const int channel = input.value("channel", -1);
    if (channel < 0 || channel > 3) continue;
    const std::string ctype = input.value("ctype", "");
    if (ctype == "cubemap") samplers[channel] = "samplerCube";
    if (ctype == "volume") samplers[channel] = "sampler3D";
  }
  std::string header =
      "#version 300 es\nprecision highp float;\nprecision highp int;\n"
      "precision mediump sampler3D;\n#define HW_PERFORMANCE 1\n"
      "uniform vec3 iResolution;\nuniform float iTime;\nuniform float iChannelTime[4];\n"
      "uniform vec4 iMouse;\nuniform vec4 iDate;\nuniform float iSampleRate;\n"
      "uniform vec3 iChannelResolution[4];\nuniform int iFrame;\nuniform float iTimeDelta;\n"
      "uniform float iFrameRate;\n";
  for (int i = 0; i < 4; ++i) {
    header += "uniform " + samplers[i] + " iChannel" + std::to_string(i) + ";\n";
  }
  return header + "void mainImage(out vec4 c, in vec2 f);\n";
}

struct Pass {
  std::string id;
  std::string text;
};

std::vector<Pass> ImagePasses() {
  std::vector<Pass> passes;
  std::istringstream in(
      ReadText(fs::path(SHADERPORT_SHARED_DIR) / "corpus-shadertoy/permissive.jsonl"));
  for (std::string line; std::getline(in, line);) {
    const nlohmann::json shader = nlohmann::json::parse(line, nullptr, false);
    if (shader.is_discarded()) continue;
    std::string common;
    for (const auto& pass : shader["passes"]) {
      if (pass["type"] == "common") common += pass["code"].get<std::string>() + "\n";
    }
    for (const auto& pass : shader["passes"]) {
      if (pass["type"] != "image") continue;
      passes.push_back({shader["id"], Header(pass["inputs"]) + common +
                                          pass["code"].get<std::string>() +
                                          testing::kShaderToyFooter});
    }
  }
  return passes;
}

TEST(ShaderToySweep, ValidImagePassesGoThroughEveryBackEnd) {
  const std::vector<Pass> passes = ImagePasses();
  if (passes.empty()) GTEST_SKIP() << "no ShaderToy corpus under " << SHADERPORT_SHARED_DIR;
  std::map<std::string, int> failures;  // rule id -> count
  int valid = 0;
  int emitted = 0;
  // Every 5th pass (every 20th through all back ends) keeps the sweep within seconds in Debug.
  for (size_t i = 0; i < passes.size(); i += 5) {
    const Pass& pass = passes[i];
    if (!GlslangErrors(pass.text, model::Stage::kFragment).empty()) continue;
    ++valid;
    SCOPED_TRACE(pass.id);
    const EmitResult spirv =
        EmitText(pass.text, model::Stage::kFragment, OptionsFor(EmitKind::kSpirv), pass.id);
    if (!spirv.diagnostics.empty()) {
      for (const Diagnostic& d : spirv.diagnostics) {
        EXPECT_TRUE(d.rule_id == "spirv/leg-limitation" || d.rule_id == "spirv/invalid-module")
            << RuleIds(spirv.diagnostics);
      }
      ++failures[spirv.diagnostics.front().rule_id];
      continue;
    }
    ++emitted;
    EXPECT_GT(spirv.words_before, 0u);
    if (i % 20 != 0) continue;
    for (const EmitKind kind : {EmitKind::kHlsl, EmitKind::kMsl, EmitKind::kEsslRoundtrip}) {
      const EmitResult result =
          EmitText(pass.text, model::Stage::kFragment, OptionsFor(kind), pass.id);
      EXPECT_TRUE(result.diagnostics.empty()) << EmitKindName(kind) << RuleIds(result.diagnostics);
      EXPECT_FALSE(result.output.empty());
      if (kind == EmitKind::kEsslRoundtrip) {
        EXPECT_EQ(GlslangErrors(result.output, model::Stage::kFragment), "") << result.output;
      }
    }
  }
  std::string summary;
  for (const auto& [rule, count] : failures) summary += rule + "=" + std::to_string(count) + " ";
  std::cout << "[ShaderToySweep] " << passes.size() << " image passes, " << valid
            << " valid WebGL2, " << emitted << " emitted, failures: " << summary << "\n";
  EXPECT_GE(valid, 100);
  EXPECT_GE(emitted * 100, valid * 97) << summary;  // the leg fails on under 3% of valid passes
}

}  // namespace
}  // namespace shaderport::toolchain
