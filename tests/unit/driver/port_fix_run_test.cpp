// The `port` and `fix` pipelines as library calls (driver::RunPort, driver::RunFix),
// with the input walk and config lookup they share with `check`: no CLI involved.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "driver/input_selection.h"
#include "driver/port/fix_run.h"
#include "driver/port/port_run.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

constexpr const char* kImage =
    "void mainImage(out vec4 o, in vec2 p) {\n  o = vec4(half_of(1.0));\n}\n";
constexpr const char* kCommon = "float half_of(float x) { return x * 0.5; }\n";
// A WebGL1 pair whose varying changes type between the stages: each ports, the
// program does not link.
constexpr const char* kVertex =
    "attribute vec3 position;\nvarying vec3 vColor;\nvoid main() {\n  vColor = position;\n"
    "  gl_Position = vec4(position, 1.0);\n}\n";
constexpr const char* kFragment =
    "precision mediump float;\nvarying vec2 vColor;\nvoid main() {\n"
    "  gl_FragColor = vec4(vColor, 0.0, 1.0);\n}\n";
// ShaderToy code with an int where a float belongs: `fix` repairs it in place.
constexpr const char* kFixable =
    "void mainImage(out vec4 o, in vec2 p) {\n  float x = 1;\n  o = vec4(x);\n}\n";

class PortFixRunTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("shaderport-runs-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }

  void Write(const fs::path& relative, const std::string& text) const {
    fs::create_directories((root_ / relative).parent_path());
    std::ofstream(root_ / relative, std::ios::binary) << text;
  }
  std::string Read(const fs::path& relative) const {
    std::ifstream in(root_ / relative, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  std::vector<InputFile> Select(const std::vector<fs::path>& relative_paths) const {
    InputSelectionOptions options;
    for (const fs::path& path : relative_paths) options.paths.push_back(root_ / path);
    ConfiguredInputs inputs = SelectConfiguredInputs(options);
    EXPECT_TRUE(inputs.selection.errors.empty());
    return inputs.selection.files;
  }
  static bool HasRule(const std::vector<PortResult>& results, const std::string& rule) {
    return std::any_of(results.begin(), results.end(), [&](const PortResult& result) {
      return std::any_of(result.diagnostics.begin(), result.diagnostics.end(),
                         [&](const Diagnostic& d) { return d.rule_id == rule; });
    });
  }

  fs::path root_;
};

TEST_F(PortFixRunTest, SelectionAppliesTheConfigsGlobsAndFilesEntries) {
  Write("p/.shaderport.toml",
        "[check]\nexclude = [\"vendor/**\"]\n[[files]]\nglob = \"toy/**\"\ndialect = "
        "\"shadertoy\"\nstage = \"fragment\"\n");
  Write("p/vendor/a.glsl", kImage);
  Write("p/toy/b.glsl", kImage);
  Write("p/c.frag", kFragment);
  InputSelectionOptions options;
  options.paths = {root_ / "p"};
  const ConfiguredInputs inputs = SelectConfiguredInputs(options);
  const InputSelection& selection = inputs.selection;
  EXPECT_TRUE(selection.errors.empty());
  EXPECT_FALSE(selection.ConfigFailed());
  EXPECT_EQ(selection.dropped, 1u);  // vendor/a.glsl
  ASSERT_EQ(selection.files.size(), 2u);
  EXPECT_EQ(selection.files[0].relative, "c.frag");
  EXPECT_FALSE(selection.files[0].dialect);
  EXPECT_EQ(selection.files[1].relative, "toy/b.glsl");
  EXPECT_EQ(selection.files[1].dialect, Dialect::kShaderToy);
  EXPECT_EQ(selection.files[1].stage, model::Stage::kFragment);

  // The text of --stdin counts as the named file: excluded there, it is dropped.
  InputSelectionOptions named;
  named.stdin_name = root_ / "p/vendor/new.glsl";
  EXPECT_EQ(SelectConfiguredInputs(named).selection.dropped, 1u);
  named.force_exclude = false;
  EXPECT_EQ(SelectConfiguredInputs(named).selection.files.size(), 1u);
}

TEST_F(PortFixRunTest, ABrokenConfigIsAProblemOfItsOwnAndAMissingOneAnError) {
  Write("q/.shaderport.toml", "[check\n");
  Write("q/a.frag", kFragment);
  InputSelectionOptions options;
  options.paths = {root_ / "q"};
  const ConfiguredInputs inputs = SelectConfiguredInputs(options);
  EXPECT_TRUE(inputs.selection.ConfigFailed());
  ASSERT_EQ(inputs.selection.config_problems.size(), 1u);
  EXPECT_EQ(inputs.selection.config_problems[0].file->Name(),
            (root_ / "q/.shaderport.toml").string());
  EXPECT_EQ(inputs.selection.files.size(), 1u);

  options.config = root_ / "q/missing.toml";
  const ConfiguredInputs missing = SelectConfiguredInputs(options);
  ASSERT_EQ(missing.selection.errors.size(), 1u);
  EXPECT_NE(missing.selection.errors[0].find("no such file"), std::string::npos);
  EXPECT_TRUE(missing.selection.files.empty());
}

TEST_F(PortFixRunTest, AProjectFolderPortsToItsPassesUnderTheOutDir) {
  Write("toy/shadertoy.toml", "name = 'Toy'\n");
  Write("toy/image.glsl", kImage);
  Write("toy/common.glsl", kCommon);
  SourceManager sources;
  PortRunOptions options;
  options.out_dir = root_ / "out";
  const PortRun run = RunPort(Select({"toy"}), options, sources);
  EXPECT_TRUE(run.usage_error.empty()) << run.usage_error;
  EXPECT_TRUE(run.write_errors.empty());
  EXPECT_FALSE(run.unsettled);
  EXPECT_TRUE(run.standard_output.empty());
  // The folder is one project: its tab files do not give outputs of their own.
  ASSERT_EQ(run.results.size(), 1u);
  const std::string image = Read("out/toy/image.frag");
  EXPECT_TRUE(image.starts_with("#version 300 es\n")) << image;
  EXPECT_NE(image.find("float half_of(float x)"), std::string::npos);  // Common inlined
  EXPECT_FALSE(fs::exists(root_ / "out/toy/common.frag"));
}

TEST_F(PortFixRunTest, StagesPortedTogetherAreLinkedAndBothWritten) {
  Write("prog/a.vert", kVertex);
  Write("prog/a.frag", kFragment);
  SourceManager sources;
  PortRunOptions options;
  options.out_dir = root_ / "out";
  const PortRun run = RunPort(Select({"prog"}), options, sources);
  EXPECT_TRUE(run.usage_error.empty()) << run.usage_error;
  ASSERT_EQ(run.results.size(), 2u);
  EXPECT_TRUE(HasRule(run.results, "port/stages-do-not-link"));
  EXPECT_NE(Read("out/a.vert").find("out vec3 vColor;"), std::string::npos);
  EXPECT_NE(Read("out/a.frag").find("in vec2 vColor;"), std::string::npos);
}

TEST_F(PortFixRunTest, OneShaderGoesToStandardOutputAndSeveralNeedAnOutDir) {
  Write("prog/a.frag", kFragment);
  Write("prog/b.frag", kFragment);
  SourceManager sources;
  const PortRun one = RunPort(Select({"prog/a.frag"}), PortRunOptions{}, sources);
  EXPECT_TRUE(one.standard_output.starts_with("#version 300 es\n")) << one.standard_output;
  const PortRun two = RunPort(Select({"prog"}), PortRunOptions{}, sources);
  EXPECT_NE(two.usage_error.find("standard output takes one shader"), std::string::npos);
  EXPECT_TRUE(two.results.empty());  // refused before porting
}

TEST_F(PortFixRunTest, OutputsThatWouldCollideAreRefusedBeforeAnythingIsWritten) {
  Write("s/x.glsl", kFixable);  // both give x.frag
  Write("s/x.frag", kFragment);
  SourceManager sources;
  PortRunOptions options;
  options.out_dir = root_ / "out";
  const PortRun run = RunPort(Select({"s"}), options, sources);
  EXPECT_NE(run.usage_error.find("would both be written to"), std::string::npos) << run.usage_error;
  EXPECT_FALSE(fs::exists(root_ / "out"));
}

TEST_F(PortFixRunTest, FixInPlaceRewritesOnlyFilesThatChange) {
  Write("f/fixable.glsl", kFixable);
  Write("f/clean.frag", kFragment);
  const fs::file_time_type clean_time = fs::last_write_time(root_ / "f/clean.frag");
  SourceManager sources;
  FixRunOptions options;
  options.destination = FixDestination::kInPlace;
  const FixRun run = RunFix(Select({"f"}), options, sources);
  EXPECT_TRUE(run.write_errors.empty());
  EXPECT_FALSE(run.unreadable);
  EXPECT_FALSE(run.unsettled);
  EXPECT_TRUE(run.standard_output.empty());
  ASSERT_EQ(run.results.size(), 2u);
  EXPECT_NE(Read("f/fixable.glsl").find("float x = 1.0;"), std::string::npos);
  EXPECT_EQ(Read("f/clean.frag"), kFragment);
  EXPECT_EQ(fs::last_write_time(root_ / "f/clean.frag"), clean_time);
}

TEST_F(PortFixRunTest, FixDiffLeavesTheFilesAndGivesTheDiff) {
  Write("f/fixable.glsl", kFixable);
  SourceManager sources;
  FixRunOptions options;
  options.destination = FixDestination::kDiff;
  const FixRun run = RunFix(Select({"f"}), options, sources);
  EXPECT_NE(run.standard_output.find("-  float x = 1;\n+  float x = 1.0;\n"), std::string::npos)
      << run.standard_output;
  EXPECT_EQ(Read("f/fixable.glsl"), kFixable);
}

TEST_F(PortFixRunTest, FixOfTextKeepsItsByteOrderMarkAndUnreadableTextIsSaid) {
  SourceManager sources;
  FixRunOptions options;
  const FixRun fixed =
      RunFixOnText(root_ / "piped.glsl", ClassifyInputText(std::string("\xEF\xBB\xBF") + kFixable),
                   options, sources);
  EXPECT_TRUE(fixed.standard_output.starts_with("\xEF\xBB\xBF")) << fixed.standard_output;
  EXPECT_NE(fixed.standard_output.find("float x = 1.0;"), std::string::npos);
  const FixRun binary = RunFixOnText(root_ / "piped.glsl",
                                     ClassifyInputText(std::string("a\0b", 3)), options, sources);
  EXPECT_TRUE(binary.unreadable);
  EXPECT_TRUE(binary.standard_output.empty());
}

TEST_F(PortFixRunTest, UnchangedTextGoesWhereTheFixWouldHaveGone) {
  FixRunOptions options;
  EXPECT_EQ(ReturnUnchanged("text", options).standard_output, "text");
  options.destination = FixDestination::kDiff;
  EXPECT_TRUE(ReturnUnchanged("text", options).standard_output.empty());
  options.destination = FixDestination::kFile;
  options.output = root_ / "kept.glsl";
  EXPECT_TRUE(ReturnUnchanged("text", options).write_errors.empty());
  EXPECT_EQ(Read("kept.glsl"), "text");
}

}  // namespace
}  // namespace shaderport::driver
