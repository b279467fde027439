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
}  // namespace shaderport::render
