#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/limits.h"
#include "driver/input_files.h"
#include "driver/port/output_files.h"
#include "driver/read_input.h"
#include "report/statistics.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

class WalkInputsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("shaderport-walk-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    for (const char* file : {"s/a/b.glsl", "s/top.frag", "s/skip/x.frag", "s/.git/y.frag"}) {
      fs::create_directories((root_ / file).parent_path());
      std::ofstream(root_ / file) << "x";
    }
  }
  void TearDown() override { fs::remove_all(root_); }
  fs::path root_;
};

TEST_F(WalkInputsTest, RelativePathsAreBelowTheirDirectoryOrAsNamed) {
  const InputSet inputs = WalkInputs({root_ / "s/", root_ / "s/top.frag", "no/such.frag"});
  ASSERT_EQ(inputs.files.size(), 3u);
  EXPECT_EQ(inputs.files[0].relative, "a/b.glsl");
  EXPECT_EQ(inputs.files[1].relative, "skip/x.frag");
  EXPECT_EQ(inputs.files[2].relative, "top.frag");
  // Reached first through the directory, so not "named" though named again later.
  EXPECT_FALSE(inputs.files[2].named);
  ASSERT_EQ(inputs.errors.size(), 1u);
  EXPECT_EQ(inputs.errors[0], "no/such.frag: no such file or directory");
}

TEST_F(WalkInputsTest, TheFilterDropsOnlyWalkedFiles) {
  const auto keep = [](const fs::path& file) { return file.parent_path().filename() != "skip"; };
  const InputSet inputs = WalkInputs({root_ / "s", root_ / "s/skip/x.frag"}, keep);
  ASSERT_EQ(inputs.files.size(), 3u);
  EXPECT_EQ(inputs.files[0].relative, "a/b.glsl");
  EXPECT_EQ(inputs.files[1].relative, "top.frag");
  EXPECT_TRUE(inputs.files[2].named);
  EXPECT_EQ(inputs.files[2].path, root_ / "s/skip/x.frag");
  EXPECT_EQ(inputs.files[2].relative, (root_ / "s/skip/x.frag").lexically_normal());
}

TEST_F(WalkInputsTest, FilterNamedDropsNamedFilesTooAndCountsWhatItDropped) {
  const auto keep = [](const fs::path& file) { return file.parent_path().filename() != "skip"; };
  const InputSet inputs = WalkInputs({root_ / "s", root_ / "s/skip/x.frag"}, keep, true);
  ASSERT_EQ(inputs.files.size(), 2u);
  EXPECT_EQ(inputs.files[0].relative, "a/b.glsl");
  EXPECT_EQ(inputs.files[1].relative, "top.frag");
  EXPECT_EQ(inputs.dropped, 2u);  // s/skip/x.frag, found by the walk and named
}

TEST(OutDirPathTest, StaysInsideTheDirectory) {
  EXPECT_EQ(OutDirPath("out", "a/b.glsl", ".frag"), fs::path("out/a/b.frag"));
  EXPECT_EQ(OutDirPath("out", "./a/../c.vs", ".vert"), fs::path("out/c.vert"));
  EXPECT_EQ(OutDirPath("out", "../../x/c.glsl", ".spv"), fs::path("out/x/c.spv"));
  EXPECT_EQ(OutDirPath("out", "/abs/dir/c.glsl", ".frag"), fs::path("out/c.frag"));
}

TEST(OutputClashTest, NamesTwoInputsForOneTargetAndAReplacedInput) {
  EXPECT_EQ(OutputClash({"a.glsl", "b.glsl"}, {"o/a.frag", "o/b.frag"}), "");
  EXPECT_EQ(OutputClash({"a.glsl", "b.glsl"}, {"o/a.frag", ""}), "");
  EXPECT_EQ(OutputClash({"x/a.glsl", "y/a.frag"}, {"o/a.frag", "o/./a.frag"}),
            "x/a.glsl and y/a.frag would both be written to o/./a.frag");
  EXPECT_EQ(OutputClash({"a.glsl", "o/b.frag"}, {"o/a.frag", "o/b.frag"}),
            "the result of o/b.frag (o/b.frag) would replace the input o/b.frag");
}

TEST(OutputClashTest, AHardLinkToAnInputIsTheInput) {
  const fs::path dir = fs::temp_directory_path() / ("clash-" + std::to_string(::getpid()));
  fs::create_directories(dir / "o");
  std::ofstream(dir / "a.glsl") << "x";
  fs::create_hard_link(dir / "a.glsl", dir / "o" / "a.frag");
  EXPECT_EQ(OutputClash({dir / "a.glsl"}, {dir / "o" / "a.frag"}),
            "the result of " + (dir / "a.glsl").string() + " (" + (dir / "o" / "a.frag").string() +
                ") would replace the input " + (dir / "a.glsl").string());
  fs::remove_all(dir);
}

TEST(ReadInputStreamTest, ReadsTextAndStopsPastTheLimit) {
  std::istringstream text("void main() {}\n");
  EXPECT_EQ(ReadInputStream(text).text, "void main() {}\n");
  std::istringstream big(std::string(limits::kMaxFileBytes + 1, 'a'));
  const InputText rejected = ReadInputStream(big);
  EXPECT_FALSE(rejected.text);
  EXPECT_EQ(rejected.rule_id, "input/too-large");
  // Reading stopped long before the end of a larger stream.
  std::istringstream huge(std::string(3 * limits::kMaxFileBytes, 'a'));
  EXPECT_EQ(ReadInputStream(huge).rule_id, "input/too-large");
  EXPECT_LT(static_cast<size_t>(huge.tellg()), limits::kMaxFileBytes + (1u << 17));
}

TEST(StatisticsTest, CountsRulesMostFrequentFirstThenById) {
  SourceManager sources;
  const SourceFile& file = sources.Add("a.frag", "x");
  CheckReport report;
  report.sources = &sources;
  FileReport entry;
  entry.file = &file;
  auto add = [&](const char* id, Severity severity) {
    Diagnostic d;
    d.rule_id = id;
    d.severity = severity;
    entry.diagnostics.push_back(d);
  };
  add("zz/made-up", Severity::kNote);
  add("zz/made-up", Severity::kWarning);
  add("glslang/type-mismatch", Severity::kError);
  add("aa/made-up", Severity::kNote);
  report.files.push_back(entry);
  const std::vector<RuleCount> counts = CountByRule(report);
  ASSERT_EQ(counts.size(), 3u);
  EXPECT_EQ(counts[0].rule_id, "zz/made-up");
  EXPECT_EQ(counts[0].count, 2u);
  EXPECT_EQ(counts[0].severity, Severity::kWarning);  // the most severe seen
  EXPECT_EQ(counts[1].rule_id, "aa/made-up");
  EXPECT_EQ(counts[2].rule_id, "glslang/type-mismatch");
  EXPECT_EQ(FormatStatistics(counts),
            "2  zz/made-up             warning\n"
            "1  aa/made-up             note\n"
            "1  glslang/type-mismatch  error    "
            "A value cannot be converted to the type it is assigned to\n");
  EXPECT_EQ(FormatStatistics({}), "");
}

}  // namespace
}  // namespace shaderport::driver
