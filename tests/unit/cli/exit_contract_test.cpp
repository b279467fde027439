// The exit-code and error-message contract of docs/cli.md ("Exit codes and errors"),
// one table over every command: 0 clean, 1 findings at or above --fail-on, 2 usage
// or input errors, each said as `shaderport: error: ...` on standard error.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_test_util.h"
#include "cli/temp_project.h"

namespace shaderport::testing {
namespace {

struct ContractCase {
  std::string args;
  int exit_code;
  std::string error;  // the whole first line of standard error for exit 2, else ""
};

// Old styles the contract replaced: "shaderport check: ...", CLI11's own words.
bool HasForeignErrorLine(const std::string& err) {
  std::istringstream lines(err);
  for (std::string line; std::getline(lines, line);) {
    if (line.starts_with("shaderport ") || line.starts_with("The following argument") ||
        line.starts_with("Run with --help") || line.find("is required") == 0) {
      return true;
    }
  }
  return false;
}

TEST(ExitContract, EveryCommandExitsAndSpeaksAsDocumented) {
  TempProject project("exit-contract");
  project.Write("clean.frag", kWebGL1Fragment);
  project.Write("broken.frag", "void main() { float x = ; }\n");
  project.Write("fixable.frag", kFixableEssl3);
  project.Write("empty/notes.txt", "not a shader\n");
  // Only a warning no fix can repair: GLSL ES 1.00 has no zero for an array.
  project.Write("warning.frag",
                "precision mediump float;\nvoid main() {\n  int i = 0;\n  float a[4];\n"
                "  gl_FragColor = vec4(a[i]);\n}\n");
  ASSERT_EQ(RunShaderport("check --format json clean.frag > clean.json", project.Root()).exit_code,
            0);

  const std::vector<ContractCase> table = {
      // No command, help, unknown commands.
      {"", 2,
       "shaderport: error: no command given (run 'shaderport help' for the list of commands)"},
      {"help", 0, ""},
      {"help check", 0, ""},
      {"check --help", 0, ""},
      {"--version", 0, ""},
      {"chek", 2,
       "shaderport: error: unknown command 'chek'; did you mean 'check'? (run 'shaderport help' "
       "for the list of commands)"},
      {"help chek", 2,
       "shaderport: error: unknown command 'chek'; did you mean 'check'? (run 'shaderport help' "
       "for the list of commands)"},
      {"lint x", 2,
       "shaderport: error: unknown command 'lint' (run 'shaderport help' for the list of "
       "commands)"},
      {"--verison", 2,
       "shaderport: error: unknown option '--verison'; did you mean '--version'? (options go after "
       "the command: 'shaderport help COMMAND')"},
      {"check --jobs many clean.frag", 2,
       "shaderport: error: check: invalid value 'many' for --jobs"},
      // check
      {"check clean.frag", 0, ""},
      {"check broken.frag", 1, ""},
      {"check missing.frag", 2, "shaderport: error: missing.frag: no such file or directory"},
      {"check --fromat json clean.frag", 2,
       "shaderport: error: unknown option '--fromat' for 'check'; did you mean '--format'?"},
      {"check --format jsn clean.frag", 2,
       "shaderport: error: unknown --format 'jsn'; did you mean 'json'?"},
      {"check --format xml clean.frag", 2,
       "shaderport: error: unknown --format 'xml' (expected text, json, sarif or github)"},
      {"check --target wbgl2 clean.frag", 2,
       "shaderport: error: unknown --target 'wbgl2'; did you mean 'webgl2'?"},
      {"check --dialect shadertoi clean.frag", 2,
       "shaderport: error: unknown --dialect 'shadertoi'; did you mean 'shadertoy'?"},
      {"check --color sometimes clean.frag", 2,
       "shaderport: error: unknown --color 'sometimes' (expected auto, always or never)"},
      {"check --config nope.toml clean.frag", 2,
       "shaderport: error: --config nope.toml: no such file"},
      {"check --format", 2, "shaderport: error: check: option '--format' needs a value"},
      {"check empty", 2,
       "shaderport: error: no shader files to check in 'empty' (--allow-empty accepts an empty "
       "run)"},
      {"check --allow-empty empty", 0, ""},
      // fix
      {"fix clean.frag", 0, ""},
      {"fix warning.frag", 0, ""},
      {"fix --fail-on warning warning.frag", 1, ""},
      {"fix --fail-on warn warning.frag", 2,
       "shaderport: error: unknown --fail-on 'warn'; did you mean 'warning'?"},
      {"fix empty", 2,
       "shaderport: error: no shader files to fix in 'empty' (--allow-empty accepts an empty run)"},
      {"fix broken.frag", 1, ""},
      {"fix missing.frag", 2, "shaderport: error: missing.frag: no such file or directory"},
      {"fix --in-plac clean.frag", 2,
       "shaderport: error: unknown option '--in-plac' for 'fix'; did you mean '--in-place'?"},
      {"fix --config nope.toml clean.frag", 2,
       "shaderport: error: --config nope.toml: no such file"},
      {"fix --diff -i clean.frag", 2,
       "shaderport: error: fix: --diff and --in-place cannot be used together"},
      // port
      {"port clean.frag", 0, ""},
      {"port --fail-on note clean.frag", 0, ""},
      {"port broken.frag", 1, ""},
      {"port --write-invalid broken.frag", 1, ""},
      {"port clean.frag fixable.frag", 2,
       "shaderport: error: the paths hold 2 input files and standard output takes one shader: use "
       "--out-dir DIR"},
      {"port missing.frag", 2, "shaderport: error: missing.frag: no such file or directory"},
      {"port --emit spirvv clean.frag", 2,
       "shaderport: error: unknown --emit 'spirvv'; did you mean 'spirv'?"},
      {"port --stage vertx clean.frag", 2,
       "shaderport: error: unknown --stage 'vertx'; did you mean 'vertex'?"},
      {"port --config nope.toml clean.frag", 2,
       "shaderport: error: --config nope.toml: no such file"},
      // render
      {"render --size 8x8 clean.frag", 0, ""},
      {"render --size 8x8 --fail-on note broken.frag", 1, ""},
      {"render missing.frag", 2, "shaderport: error: missing.frag: no such file or directory"},
      {"render --backend osmsa clean.frag", 2,
       "shaderport: error: unknown --backend 'osmsa'; did you mean 'osmesa'?"},
      {"render", 2, "shaderport: error: render: file is required"},
      {"render -o /nonexistent/x.png clean.frag", 2,
       "shaderport: error: cannot write /nonexistent/x.png: no such directory /nonexistent"},
      {"render clean.frag broken.frag", 2,
       "shaderport: error: unexpected argument 'broken.frag' for 'render'"},
      // report
      {"report --html page.html --size 8 clean.frag", 0, ""},
      {"report --html page.html --size 8 missing.frag", 2,
       "shaderport: error: missing.frag: no such file or directory"},
      {"report clean.frag", 2, "shaderport: error: report: --html is required"},
      // merge
      {"merge clean.json", 0, ""},
      {"merge missing.json", 2,
       "shaderport: error: missing.json: cannot open file: No such file or directory"},
      {"merge --format jsn clean.json", 2,
       "shaderport: error: unknown --format 'jsn'; did you mean 'json'?"},
      // rules, explain
      {"rules", 0, ""},
      {"rules --list", 0, ""},
      {"rules --bogus", 2, "shaderport: error: unknown option '--bogus' for 'rules'"},
      {"explain port/version", 0, ""},
      {"explain port/versoin", 2,
       "shaderport: error: unknown rule 'port/versoin'; did you mean 'port/version'? (run "
       "'shaderport rules' for the porting rules)"},
      // dump, summary, version
      {"dump --ast clean.frag", 0, ""},
      {"dump --ast broken.frag", 1, ""},
      {"dump --ast missing.frag", 2, "shaderport: error: missing.frag: no such file or directory"},
      {"dump clean.frag", 2,
       "shaderport: error: give exactly one of --tokens, --pp-tokens, --ast, --types"},
      {"summary clean.frag", 0, ""},
      {"summary missing.frag", 2, "shaderport: error: missing.frag: no such file or directory"},
      // completion, man
      {"help help", 0, ""},
      {"help completion", 0, ""},
      {"completion bash", 0, ""},
      {"completion zsh", 0, ""},
      {"completion fish", 0, ""},
      {"completion tcsh", 2,
       "shaderport: error: unknown shell 'tcsh' (expected bash, zsh or fish)"},
      {"completion", 2, "shaderport: error: completion: shell is required"},
      {"man", 0, ""},
      {"man extra", 2, "shaderport: error: unexpected argument 'extra' for 'man'"},
      {"help lsp", 0, ""},
      {"lsp --stdio-extra", 2, "shaderport: error: unknown option '--stdio-extra' for 'lsp'"},
      {"version", 0, ""},
      {"version extra", 2, "shaderport: error: unexpected argument 'extra' for 'version'"},
  };
  for (const ContractCase& row : table) {
    const CommandResult result = RunShaderport(row.args, project.Root());
    SCOPED_TRACE("shaderport " + row.args + "\nstderr:\n" + result.err);
    EXPECT_EQ(result.exit_code, row.exit_code);
    EXPECT_FALSE(HasForeignErrorLine(result.err));
    if (row.exit_code == 2) {
      EXPECT_EQ(result.err.substr(0, result.err.find('\n')), row.error);
    }
  }
}

TEST(ExitContract, AnUnwritableRenderOutputFailsBeforeDrawing) {
  TempProject project("exit-render-output");
  project.Write("clean.frag", kWebGL1Fragment);
  const CommandResult result =
      RunShaderport("render -o /nonexistent/x.png clean.frag", project.Root());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");  // never "rendered ... -> /nonexistent/x.png"
}

TEST(ExitContract, ChannelTakesExactlyOneValue) {
  TempProject project("exit-channel");
  project.Write(
      "toy.glsl",
      "void mainImage(out vec4 o, in vec2 p) { o = texture(iChannel0, vec3(p, 1.0)); }\n");
  // The path after --channel is a path, not a second channel (it was "bad --channel").
  const CommandResult check = RunShaderport("check --channel 0=cube toy.glsl", project.Root());
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  EXPECT_NE(check.out.find("(1 file checked)"), std::string::npos) << check.out;
  const CommandResult port = RunShaderport("port --channel 0=cube toy.glsl", project.Root());
  EXPECT_EQ(port.exit_code, 0) << port.err;
  EXPECT_NE(port.out.find("samplerCube iChannel0"), std::string::npos) << port.out;
  const CommandResult render =
      RunShaderport("render --size 4x4 --channel-type 0=cube --mouse 1,2 toy.glsl", project.Root());
  EXPECT_EQ(render.exit_code, 0) << render.err;
}

TEST(ExitContract, RulesListHasOneLinePerRule) {
  const CommandResult list = RunShaderport("rules --list", SourceDir());
  ASSERT_EQ(list.exit_code, 0);
  const CommandResult markdown = RunShaderport("rules", SourceDir());
  std::istringstream lines(list.out);
  size_t count = 0;
  for (std::string line; std::getline(lines, line); ++count) {
    const std::string id = line.substr(0, line.find(' '));
    EXPECT_NE(markdown.out.find("\n## " + id + "\n"), std::string::npos) << line;
  }
  EXPECT_GT(count, 20u);
}

}  // namespace
}  // namespace shaderport::testing
