// `shaderport check --render` through the real binary.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli_test_util.h"

namespace shaderport::testing {
namespace {

namespace fs = std::filesystem;

class CheckRenderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("shaderport-check-render-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  void Write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
  }
  fs::path dir_;
};

TEST_F(CheckRenderTest, FragmentInputsAreFedAndAGoodPictureHasNoFinding) {
  Write("uv.frag",
        "#version 300 es\nprecision highp float;\nin vec2 vUv;\nout vec4 color;\n"
        "void main() { color = vec4(vUv, 0.5 + 0.5 * sin(vUv.x * 20.0), 1.0); }\n");
  const CommandResult result = RunShaderport("check --render --format github uv.frag", dir_);
  EXPECT_EQ(result.exit_code, 0) << result.out << result.err;
  EXPECT_EQ(result.out, "") << result.err;
}

TEST_F(CheckRenderTest, ConstantPictureIsAWarningAndFailsOnlyWhenAsked) {
  Write("flat.glsl", "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.25, 0.5, 0.75, 1.0); }\n");
  const CommandResult result = RunShaderport("check --render --format github flat.glsl", dir_);
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.out.find("title=render/single-colour"), std::string::npos) << result.out;
  EXPECT_EQ(RunShaderport("check --render --fail-on warning flat.glsl", dir_).exit_code, 1);
}

TEST_F(CheckRenderTest, PictureFindingsObeySuppressionComments) {
  // Picture-level findings point at the start of the file: a comment there silences them.
  Write("flat.glsl",
        "// shaderport-ignore(render/single-colour)\n"
        "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.25, 0.5, 0.75, 1.0); }\n");
  const CommandResult result = RunShaderport("check --render --format github flat.glsl", dir_);
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_EQ(result.out, "") << result.out;
}

TEST_F(CheckRenderTest, WebGL1IsRenderedThroughItsPort) {
  Write("old.frag",
        "precision mediump float;\nvarying vec2 vUv;\n"
        "void main() { gl_FragColor = vec4(vUv, 0.0, 1.0); }\n");
  const CommandResult result = RunShaderport("check --render --format github old.frag", dir_);
  EXPECT_EQ(result.exit_code, 0) << result.out;
  EXPECT_EQ(result.out, "");
}

TEST_F(CheckRenderTest, EndlessLoopIsKilledAndReported) {
  Write("loop.glsl",
        "void mainImage(out vec4 c, in vec2 p) {\n  float x = 0.0;\n"
        "  for (;;) { for (int i = 0; i < 16; ++i) x += sin(x + float(i)); if (x > 1e30) break; }\n"
        "  c = vec4(x);\n}\n");
  const CommandResult result =
      RunShaderport("check --render --render-timeout 1.5 --format github loop.glsl", dir_);
  EXPECT_EQ(result.exit_code, 1) << result.out;
  EXPECT_NE(result.out.find("title=render/timeout"), std::string::npos) << result.out;
}

TEST_F(CheckRenderTest, BadRenderOptionsAreUsageErrors) {
  Write("a.glsl", "void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n");
  EXPECT_EQ(RunShaderport("check --render --render-size 0 a.glsl", dir_).exit_code, 2);
  EXPECT_EQ(RunShaderport("check --render --render-timeout -1 a.glsl", dir_).exit_code, 2);
}

}  // namespace
}  // namespace shaderport::testing
