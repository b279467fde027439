// `check --stdin` and `fix --stdin`: the text an editor pipes in is checked as
// the file it names, which need not exist.
#include <gtest/gtest.h>

#include <string>

#include "cli/cli_test_util.h"
#include "cli/temp_project.h"

namespace shaderport::testing {
namespace {

constexpr const char* kUsesCommon =
    "void mainImage(out vec4 c, in vec2 p) { c = vec4(helper()); }\n";

TEST(StdinCli, ReportsUnderTheGivenNameWithItsCommon) {
  TempProject project("stdin-common");
  project.Write("toy/common.glsl", "float helper() { return 0.5; }\n");
  project.Write("piped.glsl", kUsesCommon);
  // toy/image.glsl does not exist: its directory's common.glsl is still compiled first.
  const CommandResult beside =
      RunShaderport("check --stdin --stdin-filename toy/image.glsl < piped.glsl", project.Root());
  EXPECT_EQ(beside.exit_code, 0) << beside.out << beside.err;
  EXPECT_NE(beside.out.find("(1 file checked)"), std::string::npos) << beside.out;
  const CommandResult elsewhere =
      RunShaderport("check --stdin --stdin-filename other/image.glsl < piped.glsl", project.Root());
  EXPECT_EQ(elsewhere.exit_code, 1);
  EXPECT_EQ(elsewhere.out.rfind("other/image.glsl:1:50: error: ", 0), 0u) << elsewhere.out;
}

TEST(StdinCli, AnExcludedStdinFilenameIsLeftAlone) {
  TempProject project("stdin-excluded");
  project.Write(".shaderport.toml", "[check]\nexclude = [\"vendor/**\"]\n");
  project.Write("piped.txt", kFixableEssl3);
  const CommandResult check =
      RunShaderport("check --stdin --stdin-filename vendor/a.frag < piped.txt", project.Root());
  EXPECT_EQ(check.exit_code, 0) << check.out;
  EXPECT_EQ(check.out, "0 errors, 0 warnings in 0 files (0 files checked)\n");
  const CommandResult fix =
      RunShaderport("fix --stdin --stdin-filename vendor/a.frag < piped.txt", project.Root());
  EXPECT_EQ(fix.exit_code, 0) << fix.err;
  EXPECT_EQ(fix.out, kFixableEssl3);  // unchanged
  const CommandResult forced =
      RunShaderport("check --no-force-exclude --stdin --stdin-filename vendor/a.frag < piped.txt",
                    project.Root());
  EXPECT_EQ(forced.exit_code, 1) << forced.out;
}

TEST(StdinCli, TheNameDecidesStageAndConfig) {
  TempProject project("stdin-config");
  project.Write("quiet/.shaderport.toml", "[rules]\n\"portability/*\" = \"off\"\n");
  project.Write("piped.txt",
                "#version 300 es\nprecision mediump float;\nout vec4 o;\n"
                "void main() { float x; o = vec4(x); }\n");
  const CommandResult plain =
      RunShaderport("check --stdin --stdin-filename a.frag < piped.txt", project.Root());
  EXPECT_NE(plain.out.find("a.frag:4:33: warning:"), std::string::npos) << plain.out;
  const CommandResult configured =
      RunShaderport("check --stdin --stdin-filename quiet/a.frag < piped.txt", project.Root());
  EXPECT_EQ(configured.out, "0 errors, 0 warnings in 0 files (1 file checked)\n");
  // A fragment shader's output in a vertex shader: the extension sets the stage.
  const CommandResult vertex = RunShaderport(
      "check --format json --stdin --stdin-filename a.vert < piped.txt", project.Root());
  EXPECT_NE(vertex.out.find("\"stage\": \"vertex\""), std::string::npos) << vertex.out;
}

TEST(StdinCli, InputBeyondTheFileLimitIsRejected) {
  TempProject project("stdin-big");
  const CommandResult result =
      RunShaderport("check --stdin --stdin-filename big.frag < /dev/zero", project.Root());
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.out.find("big.frag:1:1: error: standard input is larger than the 8 MiB limit "
                            "[input/too-large]"),
            std::string::npos)
      << result.out;
  const CommandResult empty =
      RunShaderport("check --stdin --stdin-filename e.frag < /dev/null", project.Root());
  EXPECT_NE(empty.out.find("[input/empty]"), std::string::npos) << empty.out;
}

TEST(StdinCli, FixWritesTheFixedTextToStandardOutput) {
  TempProject project("stdin-fix");
  project.Write("a.frag", kFixableEssl3);
  const CommandResult named = RunShaderport("fix a.frag", project.Root());
  const CommandResult piped =
      RunShaderport("fix --stdin --stdin-filename a.frag < a.frag", project.Root());
  EXPECT_EQ(piped.exit_code, named.exit_code) << piped.err;
  EXPECT_NE(piped.out.find("float x = 1.0;"), std::string::npos) << piped.out;
  EXPECT_EQ(piped.out, named.out);
  const CommandResult diff =
      RunShaderport("fix --diff --stdin --stdin-filename x/b.frag < a.frag", project.Root());
  EXPECT_EQ(diff.out.rfind("--- a/x/b.frag\n+++ b/x/b.frag\n", 0), 0u) << diff.out;
  EXPECT_EQ(ReadWholeFile(project.Root() / "a.frag"), kFixableEssl3);
}

TEST(StdinCli, UsageErrors) {
  TempProject project("stdin-usage");
  project.Write("a.frag", kFixableEssl3);
  EXPECT_EQ(RunShaderport("check --stdin a.frag < a.frag", project.Root()).exit_code, 2);
  EXPECT_EQ(RunShaderport("check --stdin-filename a.frag a.frag", project.Root()).exit_code, 2);
  EXPECT_EQ(RunShaderport("fix --stdin -i < a.frag", project.Root()).exit_code, 2);
  EXPECT_EQ(RunShaderport("fix --stdin a.frag < a.frag", project.Root()).exit_code, 2);
  EXPECT_EQ(RunShaderport("fix --stdin-filename a.frag a.frag", project.Root()).exit_code, 2);
  EXPECT_EQ(ReadWholeFile(project.Root() / "a.frag"), kFixableEssl3);
}

}  // namespace
}  // namespace shaderport::testing
