// `check --progress`, `--statistics` and `-q` through the binary. Tests run
// without a terminal, so `auto` progress must stay silent here.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_test_util.h"
#include "cli/temp_project.h"

namespace shaderport::testing {
namespace {

// A warning (portability/uninitialized-read) in GLSL ES 3.00.
constexpr const char* kUninitialized =
    "#version 300 es\nprecision mediump float;\nout vec4 o;\n"
    "void main() { float x; o = vec4(x); }\n";

// Two files with glslang/type-mismatch, one with portability/uninitialized-read.
void WriteFindings(const TempProject& project) {
  project.Write("s/a.frag", kFixableEssl3);
  project.Write("s/b.frag", kFixableEssl3);
  project.Write("s/c.frag", kUninitialized);
}

TEST(ProgressCli, AlwaysDrawsOnStandardErrorOnly) {
  TempProject project("progress-always");
  WriteFindings(project);
  const CommandResult result = RunShaderport("check --progress always -j 1 s", project.Root());
  EXPECT_EQ(result.exit_code, 1) << result.err;
  // The line is redrawn in place, ends at the last file and is erased afterwards.
  EXPECT_NE(result.err.find("\rchecking 1/3 files, "), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("\rchecking 3/3 files, "), std::string::npos) << result.err;
  EXPECT_NE(result.err.find(" files/s, ETA "), std::string::npos) << result.err;
  EXPECT_EQ(result.err.substr(result.err.size() - 4), "\r\x1b[K") << result.err;
  EXPECT_EQ(result.out.find("checking"), std::string::npos) << result.out;
  EXPECT_EQ(result.out.find('\r'), std::string::npos) << result.out;
}

TEST(ProgressCli, AutoAndNeverStaySilentWithoutATerminal) {
  TempProject project("progress-auto");
  WriteFindings(project);
  for (const std::string mode : {"", "--progress auto ", "--progress never "}) {
    const CommandResult result = RunShaderport("check " + mode + "s", project.Root());
    EXPECT_EQ(result.exit_code, 1) << mode;
    EXPECT_TRUE(result.err.empty()) << mode << result.err;
  }
  EXPECT_EQ(RunShaderport("check --progress sometimes s", project.Root()).exit_code, 2);
}

TEST(ProgressCli, MachineOutputStaysCleanWhenForced) {
  TempProject project("progress-json");
  WriteFindings(project);
  const CommandResult result =
      RunShaderport("check --format json --progress always s", project.Root());
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_TRUE(nlohmann::json::accept(result.out)) << result.out;
  EXPECT_NE(result.err.find("checking 3/3 files"), std::string::npos) << result.err;
}

TEST(ProgressCli, PortDrawsItsOwnLine) {
  TempProject project("progress-port");
  project.Write("s/a.frag", kWebGL1Fragment);
  project.Write("s/b.frag", kWebGL1Fragment);
  const CommandResult result =
      RunShaderport("port --progress always --out-dir out s", project.Root());
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find("\rporting 2/2 files, "), std::string::npos) << result.err;
}

TEST(StatisticsCli, CountsPerRuleAfterTheFindingsMostFrequentFirst) {
  TempProject project("statistics");
  WriteFindings(project);
  const CommandResult result = RunShaderport("check --statistics s", project.Root());
  EXPECT_EQ(result.exit_code, 1) << result.err;
  const std::string table =
      "2  glslang/type-mismatch           error    "
      "A value cannot be converted to the type it is assigned to\n"
      "1  portability/uninitialized-read  warning  "
      "A variable or out parameter may be read before it is written\n";
  // The summary line, then the count of what `fix` repairs.
  const std::string summary =
      "2 errors, 1 warning in 3 files (3 files checked)\n[*] 3 fixable with 'shaderport fix'\n";
  const size_t at = result.out.find(table);
  ASSERT_NE(at, std::string::npos) << result.out;
  // After every finding (each file's last one is c.frag's note), then the summary line last.
  EXPECT_LT(result.out.rfind("s/c.frag:"), at) << result.out;
  EXPECT_EQ(result.out.substr(at - 1), "\n" + table + summary) << result.out;
}

TEST(StatisticsCli, MachineFormatsGetTheTableOnStandardError) {
  TempProject project("statistics-json");
  WriteFindings(project);
  const CommandResult result = RunShaderport("check --format json --statistics s", project.Root());
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_TRUE(nlohmann::json::accept(result.out)) << result.out;
  EXPECT_EQ(result.err.rfind("2  glslang/type-mismatch ", 0), 0u) << result.err;
  EXPECT_EQ(result.out.find("glslang/type-mismatch    "), std::string::npos);
}

TEST(QuietCli, OnlyTheFindings) {
  TempProject project("quiet");
  WriteFindings(project);
  project.Write("clean/ok.frag", kWebGL1Fragment);
  const CommandResult loud = RunShaderport("check s", project.Root());
  const CommandResult quiet = RunShaderport("check -q s", project.Root());
  EXPECT_EQ(quiet.exit_code, 1);
  // The summary line and the count of what `fix` repairs: -q drops both.
  const std::string summary =
      "2 errors, 1 warning in 3 files (3 files checked)\n[*] 3 fixable with 'shaderport fix'\n";
  ASSERT_GT(loud.out.size(), summary.size());
  EXPECT_EQ(loud.out.substr(loud.out.size() - summary.size()), summary);
  EXPECT_EQ(quiet.out, loud.out.substr(0, loud.out.size() - summary.size()));
  const CommandResult clean = RunShaderport("check --quiet clean", project.Root());
  EXPECT_EQ(clean.exit_code, 0) << clean.err;
  EXPECT_EQ(clean.out, "");
  // With --statistics the table stays; only the summary line goes.
  const CommandResult counted = RunShaderport("check -q --statistics s", project.Root());
  EXPECT_NE(counted.out.find("1  portability/uninitialized-read"), std::string::npos);
  EXPECT_EQ(counted.out.find("files checked"), std::string::npos) << counted.out;
}

}  // namespace
}  // namespace shaderport::testing
