// What port writes: never a shader that does not compile (unless --write-invalid),
// one shader on standard output, and one layout rule for --out-dir whether the
// inputs are named files or directories.
#include <gtest/gtest.h>

#include <string>

#include "cli/cli_test_util.h"
#include "cli/temp_project.h"

namespace shaderport::testing {
namespace {

constexpr const char* kBroken =
    "void mainImage(out vec4 fragColor, in vec2 fragCoord)\n"
    "{\n"
    "    fragColor = vec4(nothing);\n"
    "}\n";

constexpr const char* kGood =
    "void mainImage(out vec4 fragColor, in vec2 fragCoord)\n"
    "{\n"
    "    fragColor = vec4(fragCoord.x);\n"
    "}\n";

TEST(PortOutputCli, AShaderThatDoesNotCompileIsNotWritten) {
  TempProject project("port-invalid");
  project.Write("bad.glsl", kBroken);
  const CommandResult result = RunShaderport("port -o out.frag bad.glsl", project.Root());
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_FALSE(project.Exists("out.frag"));
  EXPECT_NE(result.err.find("shaderport: note: bad.glsl: not written: the ported shader does not "
                            "compile (--write-invalid writes it anyway)"),
            std::string::npos)
      << result.err;
  const CommandResult printed = RunShaderport("port bad.glsl", project.Root());
  EXPECT_EQ(printed.out, "");
  const CommandResult forced =
      RunShaderport("port --write-invalid -o out.frag bad.glsl", project.Root());
  EXPECT_EQ(forced.exit_code, 1);
  EXPECT_TRUE(project.Exists("out.frag"));
}

TEST(PortOutputCli, SeveralInputsNeedOutDir) {
  TempProject project("port-several");
  project.Write("a.glsl", kGood);
  project.Write("b.glsl", kGood);
  const CommandResult result = RunShaderport("port a.glsl b.glsl", project.Root());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_NE(result.err.find("use --out-dir DIR"), std::string::npos) << result.err;
}

TEST(PortOutputCli, NamedFilesAndDirectoriesShareOneLayout) {
  TempProject project("port-layout");
  project.Write("shaders/a/b.glsl", kGood);
  project.Write("shaders/c.glsl", kGood);
  ASSERT_EQ(RunShaderport("port --out-dir one shaders", project.Root()).exit_code, 0);
  ASSERT_EQ(
      RunShaderport("port --out-dir two shaders/a/b.glsl shaders/c.glsl", project.Root()).exit_code,
      0);
  for (const std::string out : {"one", "two"}) {
    EXPECT_TRUE(project.Exists(out + "/a/b.frag")) << out;
    EXPECT_TRUE(project.Exists(out + "/c.frag")) << out;
  }
  ASSERT_EQ(RunShaderport("port --out-dir three shaders/a/b.glsl", project.Root()).exit_code, 0);
  EXPECT_TRUE(project.Exists("three/b.frag"));
}

}  // namespace
}  // namespace shaderport::testing
