// The SPIR-V leg on the corpus: every compiling corpus shader gives a module that the spirv-val
// command-line tool accepts, with and without the optimiser.
#include <gtest/gtest.h>

#include <cstring>
#include <thread>

#include "emit_test_util.h"

namespace shaderport::toolchain {
namespace {

using testing::CompilingCorpusShaders;
using testing::CorpusShader;
using testing::EmitText;
using testing::OptionsFor;
using testing::RuleIds;
using testing::SpirvValErrors;

constexpr uint32_t kSpirvMagic = 0x07230203;

TEST(SpirvEmit, CorpusHasBothStages) {
  const std::vector<CorpusShader> shaders = CompilingCorpusShaders();
  int vertex = 0;
  for (const CorpusShader& shader : shaders) vertex += shader.stage == model::Stage::kVertex;
  EXPECT_GE(shaders.size(), 22u);
  EXPECT_GE(vertex, 3);
}

TEST(SpirvEmit, EveryCorpusShaderGivesAModuleSpirvValAccepts) {
  int checked = 0;
  for (const CorpusShader& shader : CompilingCorpusShaders()) {
    for (const char* level : {"", "O", "Os"}) {
      SCOPED_TRACE(shader.path + " opt=" + level);
      EmitOptions options = OptionsFor(EmitKind::kSpirv);
      if (*level != '\0') options.optimize = level;
      const EmitResult result = EmitText(shader.webgl2, shader.stage, options, shader.path);
      ASSERT_TRUE(result.diagnostics.empty()) << RuleIds(result.diagnostics);
      ASSERT_TRUE(result.binary);
      ASSERT_EQ(result.output.size() % 4, 0u);
      ASSERT_GE(result.output.size(), 20u);
      uint32_t magic = 0;
      std::memcpy(&magic, result.output.data(), 4);
      EXPECT_EQ(magic, kSpirvMagic);
      EXPECT_EQ(result.output.size(), result.words_after * 4);
      EXPECT_GT(result.words_before, 0u);
      if (*level == '\0') {
        EXPECT_EQ(result.words_after, result.words_before);
      } else {
        EXPECT_LT(result.words_after, result.words_before);
      }
      // Os is not run through the CLI for every file: it shares the validator path with O.
      if (std::strcmp(level, "Os") != 0) {
        EXPECT_EQ(SpirvValErrors(result.output, shader.path), "");
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 44);
}

TEST(SpirvEmit, DisassemblyNamesTheEntryPointAndUniforms) {
  const std::string text =
      "#version 300 es\nprecision highp float;\nuniform vec3 iResolution;\n"
      "out vec4 color;\nvoid main() { color = vec4(iResolution, 1.0); }\n";
  const EmitResult result = EmitText(text, model::Stage::kFragment, OptionsFor(EmitKind::kSpvasm));
  ASSERT_TRUE(result.diagnostics.empty()) << RuleIds(result.diagnostics);
  EXPECT_FALSE(result.binary);
  EXPECT_EQ(result.output.rfind("; SPIR-V", 0), 0u) << result.output.substr(0, 80);
  EXPECT_NE(result.output.find("OpEntryPoint Fragment %main \"main\""), std::string::npos);
  EXPECT_NE(result.output.find("%iResolution = OpVariable"), std::string::npos);
  EXPECT_NE(result.output.find("OpDecorate %color Location 0"), std::string::npos);
}

TEST(SpirvEmit, VertexShadersGetAutomaticLocations) {
  const std::string text =
      "#version 300 es\nin vec3 position;\nin vec2 uv;\nout vec2 v_uv;\nuniform mat4 mvp;\n"
      "void main() { v_uv = uv; gl_Position = mvp * vec4(position, 1.0); }\n";
  const EmitResult result = EmitText(text, model::Stage::kVertex, OptionsFor(EmitKind::kSpvasm));
  ASSERT_TRUE(result.diagnostics.empty()) << RuleIds(result.diagnostics);
  EXPECT_NE(result.output.find("OpEntryPoint Vertex %main \"main\""), std::string::npos);
  EXPECT_NE(result.output.find("OpDecorate %position Location"), std::string::npos);
  EXPECT_NE(result.output.find("OpDecorate %v_uv Location"), std::string::npos);
}

// `port -j` emits from several threads at once: results must not depend on that.
TEST(SpirvEmit, ParallelEmitsAgreeWithSerialOnes) {
  const std::vector<CorpusShader> shaders = CompilingCorpusShaders();
  ASSERT_GE(shaders.size(), 4u);
  std::vector<std::string> serial;
  for (size_t i = 0; i < 4; ++i) {
    serial.push_back(
        EmitText(shaders[i].webgl2, shaders[i].stage, OptionsFor(EmitKind::kMsl)).output);
  }
  std::vector<std::string> parallel(4);
  std::vector<std::thread> threads;
  for (size_t i = 0; i < 4; ++i) {
    threads.emplace_back([&, i] {
      parallel[i] =
          EmitText(shaders[i].webgl2, shaders[i].stage, OptionsFor(EmitKind::kMsl)).output;
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_FALSE(serial[i].empty());
    EXPECT_EQ(parallel[i], serial[i]) << shaders[i].path;
  }
}

TEST(SpirvEmit, EsslKindReturnsTheTextUnchanged) {
  const std::string text = "#version 300 es\nvoid main() {}\n";
  const EmitResult result = EmitText(text, model::Stage::kVertex, OptionsFor(EmitKind::kEssl));
  EXPECT_EQ(result.output, text);
  EXPECT_TRUE(result.diagnostics.empty());
  EXPECT_EQ(result.words_before, 0u);
}

TEST(SpirvEmit, KindNamesRoundTrip) {
  for (const char* name : {"essl", "spirv", "spvasm", "hlsl", "msl", "essl-roundtrip", "reflect"}) {
    const std::optional<EmitKind> kind = EmitKindFromName(name);
    ASSERT_TRUE(kind.has_value()) << name;
    EXPECT_STREQ(EmitKindName(*kind), name);
  }
  EXPECT_FALSE(EmitKindFromName("glsl").has_value());
  EXPECT_FALSE(EmitKindFromName("").has_value());
  EXPECT_EQ(EmitExtension(EmitKind::kSpirv, model::Stage::kFragment), ".spv");
  EXPECT_EQ(EmitExtension(EmitKind::kEsslRoundtrip, model::Stage::kVertex), ".vert");
  EXPECT_EQ(EmitExtension(EmitKind::kMsl, model::Stage::kFragment), ".metal");
}

}  // namespace
}  // namespace shaderport::toolchain
