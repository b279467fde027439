// Shell completion and the man page are written from the option tables --help
// prints: the scripts run in the real shells (bash always; zsh and fish when the
// test machine has them, as tools/install-deps.sh installs), and the man page
// renders without a warning from groff.
#include <gtest/gtest.h>

#include <string>

#include "cli/cli_test_util.h"
#include "cli/temp_project.h"

namespace shaderport::testing {
namespace {

CommandResult RunShell(const std::string& command, const std::filesystem::path& directory) {
  return RunShellLine("cd '" + directory.string() + "' && " + command + " 2>&1");
}

bool Have(const std::string& program) {
  return RunShell("command -v " + program + " >/dev/null", "/").exit_code == 0;
}

// What bash offers after `words` (the last one is the word being completed).
std::string BashOffers(const TempProject& project, const std::string& words) {
  return RunShell("bash -c 'source ./c.bash; COMP_WORDS=(" + words +
                      "); COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); _shaderport; "
                      "printf \"%s\\n\" \"${COMPREPLY[@]}\"'",
                  project.Root())
      .out;
}

TEST(CompletionCli, BashCompletesCommandsOptionsAndClosedValues) {
  TempProject project("completion-bash");
  ASSERT_EQ(RunShaderport("completion bash > c.bash", project.Root()).exit_code, 0);
  EXPECT_EQ(BashOffers(project, "shaderport ch"), "check\n");
  EXPECT_NE(BashOffers(project, "shaderport check --fo").find("--format\n"), std::string::npos);
  EXPECT_EQ(BashOffers(project, "shaderport check --format s"), "sarif\n");
  EXPECT_EQ(BashOffers(project, "shaderport port --emit sp"), "spirv\nspvasm\n");
  EXPECT_EQ(BashOffers(project, "shaderport help rep"), "report\n");
  project.Write("shader.frag", "void main() {}\n");
  EXPECT_EQ(BashOffers(project, "shaderport check sha"), "shader.frag\n");
}

TEST(CompletionCli, AnUnknownShellIsAUsageError) {
  TempProject project("completion-unknown");
  const CommandResult result = RunShaderport("completion bsh", project.Root());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("did you mean 'bash'?"), std::string::npos) << result.err;
}

TEST(CompletionCli, ZshAndFishLoadTheirScripts) {
  TempProject project("completion-zsh-fish");
  if (Have("zsh")) {
    ASSERT_EQ(RunShaderport("completion zsh > _shaderport", project.Root()).exit_code, 0);
    // Parsed by zsh itself, and the function defined once autoloaded from fpath.
    EXPECT_EQ(RunShell("zsh -n _shaderport", project.Root()).exit_code, 0);
    const CommandResult loaded = RunShell(
        "zsh -f -c 'fpath=(. $fpath); autoload -Uz compinit; compinit -u -D; "
        "autoload -Uz _shaderport; whence -w _shaderport'",
        project.Root());
    EXPECT_NE(loaded.out.find("_shaderport: function"), std::string::npos) << loaded.out;
  }
  if (Have("fish")) {
    ASSERT_EQ(RunShaderport("completion fish > shaderport.fish", project.Root()).exit_code, 0);
    const CommandResult offered = RunShell(
        "fish --no-config -c 'source shaderport.fish; complete -C \"shaderport check --format \"'",
        project.Root());
    EXPECT_NE(offered.out.find("sarif"), std::string::npos) << offered.out;
    EXPECT_NE(offered.out.find("github"), std::string::npos) << offered.out;
  }
  if (!Have("zsh") && !Have("fish")) GTEST_SKIP() << "neither zsh nor fish is installed";
}

TEST(CompletionCli, TheManPageListsEveryCommandAndRendersCleanly) {
  TempProject project("man-page");
  ASSERT_EQ(RunShaderport("man > shaderport.1", project.Root()).exit_code, 0);
  const std::string page = ReadWholeFile(project.Root() / "shaderport.1");
  for (const std::string command :
       {"check", "fix", "port", "render", "report", "merge", "rules", "explain", "explain-file",
        "dump", "summary", "version", "completion", "man", "help"}) {
    std::string roff = command;  // a hyphen is \- in roff
    if (const size_t dash = roff.find('-'); dash != std::string::npos) roff.replace(dash, 1, "\\-");
    EXPECT_NE(page.find(".SS \"shaderport " + roff), std::string::npos) << command;
  }
  EXPECT_NE(page.find("\\fB\\-\\-fail\\-on\\fR"), std::string::npos);
  EXPECT_NE(page.find(".SH EXIT STATUS"), std::string::npos);
  if (!Have("groff")) GTEST_SKIP() << "groff is not installed";
  const CommandResult rendered = RunShell("groff -man -Tutf8 -ww -z shaderport.1", project.Root());
  EXPECT_EQ(rendered.exit_code, 0);
  EXPECT_EQ(rendered.out, "") << rendered.out;  // no warning
}

}  // namespace
}  // namespace shaderport::testing
