// Every command that takes paths walks them as `check` does: shader extensions,
// hidden directories skipped, .shaderport.toml include/exclude globs honoured.
#include <gtest/gtest.h>

#include <string>

#include "cli/cli_test_util.h"
#include "cli/temp_project.h"

namespace shaderport::testing {
namespace {

TEST(WalkCli, CheckWalksTheNestedProject) {
  TempProject project("walk-check");
  WriteNestedProject(project, kFixableEssl3);
  const CommandResult result = RunShaderport("check shaders", project.Root());
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_NE(result.out.find("shaders/a/b.glsl:4:"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("shaders/top.frag:4:"), std::string::npos) << result.out;
  EXPECT_EQ(result.out.find("vendor"), std::string::npos) << result.out;
  EXPECT_EQ(result.out.find("hidden"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("(2 files checked)"), std::string::npos) << result.out;
}

TEST(WalkCli, PortOutDirKeepsTheLayoutBelowTheDirectory) {
  TempProject project("walk-port");
  WriteNestedProject(project, kWebGL1Fragment);
  // A trailing slash names the same directory.
  const CommandResult result = RunShaderport("port --out-dir out shaders/", project.Root());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(project.Exists("out/a/b.frag"));
  EXPECT_TRUE(project.Exists("out/top.frag"));
  EXPECT_FALSE(project.Exists("out/vendor"));
  EXPECT_FALSE(project.Exists("out/.hidden"));
  EXPECT_FALSE(project.Exists("out/a/notes.frag"));
  EXPECT_EQ(ReadWholeFile(project.Root() / "out/top.frag").rfind("#version 300 es\n", 0), 0u);
}

TEST(WalkCli, PortOutDirWithSeveralRootsAndNamedFiles) {
  TempProject project("walk-port-roots");
  WriteNestedProject(project, kWebGL1Fragment);
  // Named directly, an excluded file is left out too (as ruff's --force-exclude:
  // pre-commit names every file), so shaders/a alone is laid out: below itself.
  const CommandResult result =
      RunShaderport("port --out-dir out shaders/a shaders/vendor/v.frag", project.Root());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(project.Exists("out/b.frag"));
  EXPECT_FALSE(project.Exists("out/vendor/v.frag"));
  // With --no-force-exclude both are ported, laid out alike below the deepest
  // directory that holds every argument (shaders/).
  const CommandResult named = RunShaderport(
      "port --no-force-exclude --out-dir both shaders/a shaders/vendor/v.frag", project.Root());
  ASSERT_EQ(named.exit_code, 0) << named.err;
  EXPECT_TRUE(project.Exists("both/a/b.frag"));
  EXPECT_TRUE(project.Exists("both/vendor/v.frag"));
}

TEST(WalkCli, PortOutDirRefusesClashesAndWritesNothing) {
  TempProject project("walk-port-clash");
  // Two names that differ only in the extension port replaces.
  project.Write("one/x.glsl", kWebGL1Fragment);
  project.Write("one/x.fs", kWebGL1Fragment);
  project.Write("two/x.frag", kWebGL1Fragment);
  const CommandResult clash = RunShaderport("port --out-dir out one", project.Root());
  EXPECT_EQ(clash.exit_code, 2);
  EXPECT_NE(clash.err.find("would both be written to out/x.frag"), std::string::npos) << clash.err;
  EXPECT_FALSE(project.Exists("out"));
  // Porting into the directory read from would replace the inputs themselves.
  const CommandResult over = RunShaderport("port --out-dir two two", project.Root());
  EXPECT_EQ(over.exit_code, 2);
  EXPECT_NE(over.err.find("would replace the input"), std::string::npos) << over.err;
  EXPECT_EQ(ReadWholeFile(project.Root() / "two/x.frag"), kWebGL1Fragment);
}

TEST(WalkCli, PortOutputFileTakesOneFileAfterWalking) {
  TempProject project("walk-port-o");
  WriteNestedProject(project, kWebGL1Fragment);
  const CommandResult several = RunShaderport("port -o x.frag shaders", project.Root());
  EXPECT_EQ(several.exit_code, 2);
  EXPECT_NE(several.err.find("the paths hold 2"), std::string::npos) << several.err;
  EXPECT_FALSE(project.Exists("x.frag"));
  // A directory holding one shader is one input.
  const CommandResult one = RunShaderport("port -o x.frag shaders/a", project.Root());
  EXPECT_EQ(one.exit_code, 0) << one.err;
  EXPECT_TRUE(project.Exists("x.frag"));
  EXPECT_EQ(RunShaderport("port --out-dir out missing", project.Root()).exit_code, 2);
}

TEST(WalkCli, FixInPlaceFixesEveryWalkedFile) {
  TempProject project("walk-fix");
  WriteNestedProject(project, kFixableEssl3);
  const CommandResult result = RunShaderport("fix --in-place shaders", project.Root());
  EXPECT_NE(result.exit_code, 3) << result.err;
  for (const char* fixed : {"shaders/a/b.glsl", "shaders/top.frag"}) {
    EXPECT_NE(ReadWholeFile(project.Root() / fixed).find("float x = 1.0;"), std::string::npos)
        << fixed;
  }
  for (const char* untouched : {"shaders/vendor/v.frag", "shaders/.hidden/h.frag"}) {
    EXPECT_EQ(ReadWholeFile(project.Root() / untouched), kFixableEssl3) << untouched;
  }
}

TEST(WalkCli, FixDiffShowsEveryFileAndStdoutNeedsOneFile) {
  TempProject project("walk-fix-diff");
  WriteNestedProject(project, kFixableEssl3);
  const CommandResult diff = RunShaderport("fix --diff shaders", project.Root());
  EXPECT_NE(diff.exit_code, 3) << diff.err;
  EXPECT_NE(diff.out.find("--- a/shaders/a/b.glsl\n+++ b/shaders/a/b.glsl\n"), std::string::npos)
      << diff.out;
  EXPECT_NE(diff.out.find("--- a/shaders/top.frag\n+++ b/shaders/top.frag\n"), std::string::npos)
      << diff.out;
  EXPECT_EQ(diff.out.find("vendor"), std::string::npos) << diff.out;

  const CommandResult to_stdout = RunShaderport("fix shaders", project.Root());
  EXPECT_EQ(to_stdout.exit_code, 2);
  EXPECT_TRUE(to_stdout.out.empty()) << to_stdout.out;
  EXPECT_EQ(RunShaderport("fix -o out.frag shaders", project.Root()).exit_code, 2);
  EXPECT_FALSE(project.Exists("out.frag"));
  // One file found under a directory prints as one named file does.
  const CommandResult one = RunShaderport("fix shaders/a", project.Root());
  EXPECT_NE(one.out.find("float x = 1.0;"), std::string::npos) << one.err;
}

TEST(WalkCli, ReportTakesTheSameFiles) {
  TempProject project("walk-report");
  WriteNestedProject(project, kWebGL1Fragment);
  const CommandResult result =
      RunShaderport("report --html page.html --size 8 shaders", project.Root());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find(": 2 shaders;"), std::string::npos) << result.out;
  const std::string html = ReadWholeFile(project.Root() / "page.html");
  EXPECT_NE(html.find("shaders/a/b.glsl"), std::string::npos);
  EXPECT_NE(html.find("shaders/top.frag"), std::string::npos);
  EXPECT_EQ(html.find("vendor/v.frag"), std::string::npos);
  EXPECT_EQ(html.find("h.frag"), std::string::npos);
}

TEST(WalkCli, NoConfigTakesExcludedFilesToo) {
  TempProject project("walk-no-config");
  WriteNestedProject(project, kWebGL1Fragment);
  const CommandResult result =
      RunShaderport("port --no-config --out-dir out shaders", project.Root());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(project.Exists("out/vendor/v.frag"));
  EXPECT_FALSE(project.Exists("out/.hidden"));
}

}  // namespace
}  // namespace shaderport::testing
