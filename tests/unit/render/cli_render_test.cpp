// `shaderport render` end to end (skipped when the binary is not built): the driver
// glue composes ShaderToy passes with src/validate's header and epilogue, maps Mesa's
// errors to the user's lines, and renders ShaderToy JSON exports as multipass.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "render/png_io.h"

namespace shaderport::render {
namespace {

struct CliRun {
  int exit_code = -1;
  std::string output;
};

CliRun RunCli(const std::string& arguments) {
  CliRun run;
  const std::string command = std::string(SHADERPORT_BINARY) + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return run;
  char buffer[4096];
  size_t n = 0;
  while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0) run.output.append(buffer, n);
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

class CliRender : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(SHADERPORT_BINARY)) GTEST_SKIP() << "shaderport not built";
  }
};

TEST_F(CliRender, MesaErrorIsReportedOnTheUsersLine) {
  const CliRun run = RunCli("render --hermetic " + std::string(SHADERPORT_SOURCE_DIR) +
                            "/corpus/strict-typing/float-times-int.glsl");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("float-times-int.glsl:5:"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("[render/compile-error]"), std::string::npos) << run.output;
}

TEST_F(CliRender, ShaderToyJsonRendersBuffersAsMultipass) {
  nlohmann::json shader;
  shader["passes"] = nlohmann::json::array(
      {{{"type", "image"},
        {"name", "Image"},
        {"code",
         "void mainImage(out vec4 c, in vec2 p) {\n"
         "  c = vec4(texelFetch(iChannel0, ivec2(p), 0).r, p / iResolution.xy, 1.0);\n}\n"},
        {"inputs", {{{"channel", 0}, {"ctype", "buffer"}, {"src", "/media/previz/buffer00.png"}}}}},
       {{"type", "common"}, {"name", "Common"}, {"code", "const float kStep = 0.25;\n"}},
       {{"type", "buffer"},
        {"name", "Buffer A"},
        {"code",
         "void mainImage(out vec4 c, in vec2 p) {\n"
         "  c = texelFetch(iChannel0, ivec2(p), 0) + kStep;\n}\n"},
        {"inputs",
         {{{"channel", 0}, {"ctype", "buffer"}, {"src", "/media/previz/buffer00.png"}}}}}});
  const std::string dir = ::testing::TempDir();
  const std::string json_path = dir + "/render-multipass.json";
  const std::string png_path = dir + "/render-multipass.png";
  std::ofstream(json_path) << shader.dump();
  const CliRun run =
      RunCli("render --hermetic --frames 2 --size 8x8 " + json_path + " -o " + png_path);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  ImageRgba8 image;
  std::string error;
  ASSERT_TRUE(ReadPng(png_path, image, error)) << error;
  EXPECT_EQ(image.pixels[0], 128);  // two frames of +0.25 in Buffer A, shown in red
}

// On the site a channel the record feeds nothing has no texture: sampling gives
// (0, 0, 0, 1) and iChannelResolution is 0. A fed channel gets a stand-in texture.
TEST_F(CliRender, ShaderToyJsonChannelsWithoutInputAreUnbound) {
  const std::string code =
      "void mainImage(out vec4 c, in vec2 p) {\n"
      "  c = vec4(texture(iChannel1, p / iResolution.xy).rgb, 1.0) +\n"
      "      vec4(0.0, 0.0, iChannelResolution[1].x, 0.0);\n}\n";
  const std::string dir = ::testing::TempDir();
  auto render = [&](const nlohmann::json& inputs, const std::string& name) {
    nlohmann::json shader;
    shader["passes"] = nlohmann::json::array(
        {{{"type", "image"}, {"name", "Image"}, {"code", code}, {"inputs", inputs}}});
    std::ofstream(dir + "/" + name + ".json") << shader.dump();
    const CliRun run = RunCli("render --hermetic --size 8x8 " + dir + "/" + name + ".json -o " +
                              dir + "/" + name + ".png");
    ImageRgba8 image;
    std::string error;
    EXPECT_TRUE(ReadPng(dir + "/" + name + ".png", image, error)) << error << run.output;
    return image;
  };
  const ImageRgba8 empty = render(nlohmann::json::array(), "unbound-channel");
  ASSERT_EQ(empty.pixels.size(), 8u * 8u * 4u);
  for (size_t i = 0; i < empty.pixels.size(); i += 4) {
    ASSERT_EQ(empty.pixels[i] + empty.pixels[i + 1] + empty.pixels[i + 2], 0) << i;
  }
  const ImageRgba8 fed = render(
      {{{"channel", 1}, {"ctype", "texture"}, {"src", "/media/a/noise.png"}}}, "fed-channel");
  ASSERT_EQ(fed.pixels.size(), 8u * 8u * 4u);
  EXPECT_EQ(fed.pixels[2], 255);  // iChannelResolution[1].x is the stand-in's size
}

// An Image pass carries the render probe in its alpha (one colour target for llvmpipe):
// pixels that never assign fragColor are still counted, and the picture's alpha is
// the 1 that the site forces, not the probe.
TEST_F(CliRender, ProbeInTheAlphaCountsUnassignedPixelsAndLeavesAlphaOne) {
  const std::string shader = ::testing::TempDir() + "/render-unassigned.glsl";
  const std::string png = ::testing::TempDir() + "/render-unassigned.png";
  std::ofstream(shader) << "void mainImage(out vec4 c, in vec2 p) {\n"
                           "  float s = 0.0;\n"
                           "  for (int i = 0; i < 3; i++) s += 0.25;\n"
                           "  if (p.x > 2.0) c = vec4(s, 0.5, 0.25, 0.5);\n}\n";
  const CliRun run = RunCli("render --hermetic --size 8x8 -o " + png + " " + shader);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("16 of 64 pixels never assign the colour output"), std::string::npos)
      << run.output;
  ImageRgba8 image;
  std::string error;
  ASSERT_TRUE(ReadPng(png, image, error)) << error;
  ASSERT_EQ(image.pixels.size(), 8u * 8u * 4u);
  for (size_t i = 3; i < image.pixels.size(); i += 4) ASSERT_EQ(image.pixels[i], 255) << i;
}

// A warning (the measured loop cap) fails the run only with --fail-on warning.
TEST_F(CliRender, FailOnWarningTurnsWarningsIntoAFailingExit) {
  const std::string shader =
      std::string(SHADERPORT_SOURCE_DIR) + "/tests/render-parity/shaders/long-loop.glsl";
  const CliRun plain = RunCli("render --hermetic --size 8x8 " + shader);
  EXPECT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_NE(plain.output.find("[render/loop-cap]"), std::string::npos) << plain.output;
  const CliRun strict = RunCli("render --hermetic --size 8x8 --fail-on warning " + shader);
  EXPECT_EQ(strict.exit_code, 1) << strict.output;
  EXPECT_EQ(RunCli("render --hermetic --fail-on severe " + shader).exit_code, 2);
}

TEST_F(CliRender, EndlessShaderIsKilledAndReported) {
  const std::string path = ::testing::TempDir() + "/render-endless.glsl";
  std::ofstream(path) << "#define S(x) x = sin(x) * cos(x * 1.1) + 0.1;\n"
                         "#define S8(x) S(x) S(x) S(x) S(x) S(x) S(x) S(x) S(x)\n"
                         "void mainImage(out vec4 c, in vec2 p) {\n"
                         "  float x = p.x;\n"
                         "  for (;;) { S8(x) S8(x) S8(x) S8(x) S8(x) S8(x) S8(x) S8(x)"
                         " if (x > 1e9) break; }\n"
                         "  c = vec4(x);\n}\n";
  const CliRun run = RunCli("render --hermetic --timeout 1 " + path);
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("[render/timeout]"), std::string::npos) << run.output;
}

}  // namespace
// The browser's optimiser works on the browser semantics' text, which --native drops.
TEST_F(CliRender, BrowserOptimiserDrawsAndRefusesNative) {
  const std::string shader = std::string(SHADERPORT_SOURCE_DIR) + "/corpus/ao/template.glsl";
  const CliRun optimised =
      RunCli("render --hermetic --size 8x8 --browser-optimiser -o /dev/null " + shader);
  EXPECT_EQ(optimised.exit_code, 0) << optimised.output;
  const CliRun both = RunCli("render --hermetic --native --browser-optimiser " + shader);
  EXPECT_EQ(both.exit_code, 2) << both.output;
  EXPECT_NE(both.output.find("--browser-optimiser needs the browser semantics"), std::string::npos)
      << both.output;
}

}  // namespace shaderport::render
