// Paths that hold nothing to check are usage errors unless --allow-empty; the
// config's exclude globs apply to named files too (--no-force-exclude: not); the
// summary counts what was checked, not the config file.
#include <gtest/gtest.h>

#include <string>

#include "cli/cli_test_util.h"
#include "cli/temp_project.h"

namespace shaderport::testing {
namespace {

TEST(EmptyInputCli, AnEmptyDirectoryOrUnmatchedGlobIsAUsageError) {
  TempProject project("empty-input");
  project.Write("empty/notes.txt", "not a shader\n");
  for (const std::string command : {"check", "fix", "port"}) {
    const CommandResult empty = RunShaderport(command + " empty", project.Root());
    EXPECT_EQ(empty.exit_code, 2) << command << "\n" << empty.out << empty.err;
    EXPECT_EQ(empty.err, "shaderport: error: no shader files to " + command +
                             " in 'empty' (--allow-empty accepts an empty run)\n");
    EXPECT_EQ(empty.out, "") << command;
    // The shell passes a glob that matched nothing on as written.
    const CommandResult glob = RunShaderport(command + " 'empty/*.frag'", project.Root());
    EXPECT_EQ(glob.exit_code, 2) << command;
    EXPECT_EQ(glob.err, "shaderport: error: empty/*.frag: no file matches this pattern\n");
    const CommandResult allowed =
        RunShaderport(command + " --allow-empty empty 'empty/*.frag'", project.Root());
    EXPECT_EQ(allowed.exit_code, 0) << command << "\n" << allowed.err;
  }
  EXPECT_EQ(RunShaderport("summary empty", project.Root()).exit_code, 2);
  EXPECT_EQ(RunShaderport("report --html p.html empty", project.Root()).exit_code, 2);
  EXPECT_FALSE(project.Exists("p.html"));
}

TEST(EmptyInputCli, ExcludeAppliesToNamedFilesUnlessNoForceExclude) {
  TempProject project("force-exclude");
  WriteNestedProject(project, kFixableEssl3);  // excludes shaders/vendor/**
  // As pre-commit names it: left out, and a run of excluded files only passes.
  const CommandResult named = RunShaderport("check shaders/vendor/v.frag", project.Root());
  EXPECT_EQ(named.exit_code, 0) << named.out << named.err;
  EXPECT_NE(named.out.find("(0 files checked)"), std::string::npos) << named.out;
  const CommandResult forced =
      RunShaderport("check --no-force-exclude shaders/vendor/v.frag", project.Root());
  EXPECT_EQ(forced.exit_code, 1) << forced.out;
  EXPECT_NE(forced.out.find("shaders/vendor/v.frag:4:"), std::string::npos) << forced.out;
  // fix -i leaves the excluded file alone.
  EXPECT_EQ(
      RunShaderport("fix -i shaders/vendor/v.frag shaders/top.frag", project.Root()).exit_code, 0);
  EXPECT_EQ(ReadWholeFile(project.Root() / "shaders/vendor/v.frag"), kFixableEssl3);
  EXPECT_NE(ReadWholeFile(project.Root() / "shaders/top.frag"), kFixableEssl3);
}

TEST(EmptyInputCli, TheSummaryDoesNotCountTheConfigFile) {
  TempProject project("summary-config");
  project.Write(".shaderport.toml", "[check]\nunknown = 1\n");
  project.Write("a.frag", kWebGL1Fragment);
  const CommandResult result = RunShaderport("check .", project.Root());
  EXPECT_EQ(result.exit_code, 0) << result.out;
  EXPECT_NE(result.out.find("[config/unknown-key]"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("0 errors, 1 warning in 1 file (1 file checked)"), std::string::npos)
      << result.out;
  const CommandResult json = RunShaderport("check --format json .", project.Root());
  EXPECT_NE(json.out.find("\"filesChecked\": 1"), std::string::npos) << json.out;
  // The HTML report shows the config's finding but counts one shader.
  const CommandResult page = RunShaderport("report --html p.html --size 8 .", project.Root());
  EXPECT_EQ(page.exit_code, 0) << page.err;
  EXPECT_NE(page.out.find(": 1 shaders; check 1 pass, 0 warn"), std::string::npos) << page.out;
}

}  // namespace
}  // namespace shaderport::testing
