// `check --write-baseline` and `check --baseline` through the real binary: a
// repository with findings adopts the gate, then only new findings fail it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_test_util.h"

namespace shaderport::testing {
namespace {

namespace fs = std::filesystem;

// Two findings (a float for a vec3, an int for a float) in a shader that is
// otherwise valid WebGL2.
const char* const kShader =
    "#version 300 es\n"
    "precision mediump float;\n"
    "out vec4 color;\n"
    "void main() {\n"
    "  vec3 col = 1.0;\n"
    "  float x = 2;\n"
    "  color = vec4(col * x, 1.0);\n"
    "}\n";

class BaselineCliTest : public ::testing::Test {
 protected:
  BaselineCliTest()
      : root_(fs::temp_directory_path() /
              ("shaderport-baseline-cli-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
    fs::remove_all(root_);
    fs::create_directories(root_ / "shaders");
    Write("shaders/a.frag", kShader);
    Write("shaders/b.frag", kShader);
  }
  ~BaselineCliTest() override { fs::remove_all(root_); }

  void Write(const std::string& name, const std::string& text) const {
    std::ofstream(root_ / name, std::ios::binary) << text;
  }
  CommandResult Check(const std::string& args) const {
    return RunShaderport("check --no-cache " + args + " shaders", root_);
  }
  CommandResult Adopt() const {
    const CommandResult adopted = Check("--write-baseline baseline.json");
    EXPECT_EQ(adopted.exit_code, 0) << adopted.err;
    EXPECT_NE(adopted.out.find("4 findings written to the baseline baseline.json"),
              std::string::npos)
        << adopted.out;
    return adopted;
  }

  fs::path root_;
};

TEST_F(BaselineCliTest, UnchangedAndMovedFindingsPassANewOneFails) {
  ASSERT_EQ(Check("").exit_code, 1);
  Adopt();
  const CommandResult unchanged = Check("--baseline baseline.json");
  EXPECT_EQ(unchanged.exit_code, 0) << unchanged.out;
  EXPECT_NE(unchanged.out.find("4 findings in the baseline were not reported"), std::string::npos)
      << unchanged.out;

  // Lines added above, the body re-indented: the same findings, other lines.
  std::string moved = kShader;
  moved.insert(moved.find("out vec4"), "// a comment\nuniform float time;\n\n");
  for (size_t at = moved.find("\n  "); at != std::string::npos; at = moved.find("\n  ", at + 3)) {
    moved.insert(at + 1, "    ");
  }
  Write("shaders/a.frag", moved);
  const CommandResult after_move = Check("--baseline baseline.json");
  EXPECT_EQ(after_move.exit_code, 0) << after_move.out;

  // A new finding in b.frag: only it is reported, and it fails the run.
  std::string added = kShader;
  added.insert(added.find("  color ="), "  int n = 1.5;\n");
  Write("shaders/b.frag", added);
  const CommandResult after_new = Check("--baseline baseline.json");
  EXPECT_EQ(after_new.exit_code, 1);
  EXPECT_NE(after_new.out.find("b.frag:7:"), std::string::npos) << after_new.out;
  EXPECT_EQ(after_new.out.find("a.frag"), std::string::npos) << after_new.out;
  EXPECT_NE(after_new.out.find("1 error"), std::string::npos) << after_new.out;
}

TEST_F(BaselineCliTest, FixedFindingsAreReportedRemovable) {
  Adopt();
  std::string fixed = kShader;
  fixed.replace(fixed.find("float x = 2;"), 12, "float x = 2.0;");
  Write("shaders/a.frag", fixed);
  const CommandResult run = Check("--baseline baseline.json");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("3 findings in the baseline were not reported; 1 baseline entry is "
                         "fixed; rewrite the baseline with --write-baseline"),
            std::string::npos)
      << run.out;
}

TEST_F(BaselineCliTest, MachineFormatsStayParsableAndSayNothingOfTheBaselineOnStdout) {
  Adopt();
  std::string added = kShader;
  added.insert(added.find("  color ="), "  int n = 1.5;\n");
  Write("shaders/b.frag", added);
  for (const std::string format : {"json", "sarif"}) {
    const CommandResult run = Check("--format " + format + " --baseline baseline.json");
    EXPECT_EQ(run.exit_code, 1) << format;
    const nlohmann::json document = nlohmann::json::parse(run.out);
    const size_t results = format == "json" ? document["summary"]["errors"].get<size_t>()
                                            : document["runs"][0]["results"].size();
    EXPECT_EQ(results, 1u) << format;
    EXPECT_NE(run.err.find("4 findings in the baseline were not reported"), std::string::npos)
        << run.err;
  }
}

TEST_F(BaselineCliTest, BadBaselinesAreUsageErrors) {
  EXPECT_EQ(Check("--baseline missing.json").exit_code, 2);
  Write("junk.json", "{\"version\": 99, \"findings\": []}");
  const CommandResult junk = Check("--baseline junk.json");
  EXPECT_EQ(junk.exit_code, 2);
  EXPECT_NE(junk.err.find("junk.json"), std::string::npos) << junk.err;
  // Both at once make no sense: recording would hide what the check is for.
  EXPECT_EQ(Check("--baseline a.json --write-baseline b.json").exit_code, 2);
}

// tests/data/baselines/link-varying-before-rename.json was written by shaderport before
// the program checks became link/* (its entry: webgl/link-varying), for the program
// tests/rules/link-checks/varying.*: the renamed rule's finding still matches it.
TEST(BaselineRename, ABaselineWrittenBeforeARuleWasRenamedStillMatches) {
  const fs::path programs = SourceDir() / "tests" / "rules" / "link-checks";
  const fs::path old_baseline =
      SourceDir() / "tests" / "data" / "baselines" / "link-varying-before-rename.json";
  const CommandResult result = RunShaderport(
      "check --no-config --no-cache varying.vert varying.frag --baseline " + old_baseline.string(),
      programs);
  EXPECT_EQ(result.exit_code, 0) << result.out << result.err;
  EXPECT_EQ(result.out.find("link/varying"), std::string::npos) << result.out;
  const std::string said = result.out + result.err;
  EXPECT_NE(said.find("1 finding in the baseline was not reported"), std::string::npos) << said;
  EXPECT_EQ(said.find("fixed"), std::string::npos) << said;
  // Without the baseline the finding is there, under its new id.
  const CommandResult plain =
      RunShaderport("check --no-config --no-cache varying.vert varying.frag", programs);
  EXPECT_EQ(plain.exit_code, 1);
  EXPECT_NE(plain.out.find("[link/varying]"), std::string::npos) << plain.out;
}

}  // namespace
}  // namespace shaderport::testing
