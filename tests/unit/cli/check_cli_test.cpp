// `shaderport check` through the real binary: every format on a small project
// with a config, Common code, suppressions and an excluded folder.
#include <gtest/gtest.h>

#include "cli_test_util.h"
#include "scratch_dir.h"

namespace shaderport::testing {
namespace {

const std::filesystem::path kProject = SourceDir() / "tests/data/check-project";
const std::filesystem::path kGoldens = SourceDir() / "tests/golden/cli";

class CheckFormatTest : public ::testing::TestWithParam<std::string> {};

TEST_P(CheckFormatTest, ProjectOutputMatchesGolden) {
  const std::string format = GetParam();
  const CommandResult result = RunShaderport("check --format " + format + " .", kProject);
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_EQ(result.err, "");
  const std::string extension = format == "text" ? "txt" : format;
  // SARIF names the checkout's absolute directory as %SRCROOT%: the golden
  // holds a placeholder so that it does not depend on where the tree is.
  std::string output = result.out;
  const std::string root = "file://" + kProject.string() + "/";
  for (size_t at = output.find(root); at != std::string::npos; at = output.find(root, at)) {
    output.replace(at, root.size(), "file:///PROJECT/");
  }
  EXPECT_TRUE(MatchesGolden(output, kGoldens / ("check-project." + extension)));
}

INSTANTIATE_TEST_SUITE_P(Formats, CheckFormatTest,
                         ::testing::Values("text", "json", "sarif", "github"));

TEST(CheckCliTest, OutputIsTheSameWhateverTheThreadCount) {
  const CommandResult one = RunShaderport("check --format json -j 1 .", kProject);
  const CommandResult four = RunShaderport("check --format json -j 4 .", kProject);
  EXPECT_EQ(one.out, four.out);
  EXPECT_FALSE(one.out.empty());
}

TEST(CheckCliTest, ExcludedFilesAreSkippedEvenWhenNamedUnlessNoForceExclude) {
  const CommandResult walked = RunShaderport("check .", kProject);
  EXPECT_EQ(walked.out.find("excluded/"), std::string::npos);
  // pre-commit names every staged file: exclude applies to named files too.
  const CommandResult named = RunShaderport("check excluded/broken.frag", kProject);
  EXPECT_EQ(named.out.find("excluded/"), std::string::npos) << named.out;
  EXPECT_EQ(named.exit_code, 0);
  const CommandResult forced =
      RunShaderport("check --no-force-exclude excluded/broken.frag", kProject);
  EXPECT_NE(forced.out.find("excluded/broken.frag:1:1: error"), std::string::npos) << forced.out;
  EXPECT_EQ(forced.exit_code, 1);
}

TEST(CheckCliTest, ExitCodes) {
  EXPECT_EQ(RunShaderport("check webgl1/ok.frag", kProject).exit_code, 0);
  // A warning fails only when asked to.
  EXPECT_EQ(RunShaderport("check webgl2/no-precision.frag", kProject).exit_code, 0);
  EXPECT_EQ(RunShaderport("check --fail-on warning webgl2/no-precision.frag", kProject).exit_code,
            1);
  EXPECT_EQ(RunShaderport("check webgl1/bad.vert", kProject).exit_code, 1);
  EXPECT_EQ(RunShaderport("check --format yaml .", kProject).exit_code, 2);
  EXPECT_EQ(RunShaderport("check no-such-file.frag", kProject).exit_code, 2);
  EXPECT_EQ(RunShaderport("check", kProject).exit_code, 2);
}

TEST(CheckCliTest, ColourOnlyWhenAskedOrOnATerminal) {
  const CommandResult plain = RunShaderport("check webgl1/bad.vert", kProject);
  EXPECT_EQ(plain.out.find('\x1b'), std::string::npos);
  const CommandResult forced = RunShaderport("check --color always webgl1/bad.vert", kProject);
  EXPECT_NE(forced.out.find('\x1b'), std::string::npos);
}

TEST(CheckCliTest, NoConfigMeansDefaultSeverities) {
  const CommandResult result =
      RunShaderport("check --no-config --format github webgl2/no-precision.frag", kProject);
  EXPECT_NE(result.out.find("::error "), std::string::npos) << result.out;
}

TEST(CheckCliTest, DialectAndStageOverrides) {
  // Read as a fragment shader, gl_Position is undeclared.
  const CommandResult result = RunShaderport("check --stage fragment webgl1/bad.vert", kProject);
  EXPECT_NE(result.out.find("gl_Position"), std::string::npos) << result.out;
  EXPECT_EQ(RunShaderport("check --dialect nonsense webgl1/ok.frag", kProject).exit_code, 2);
}

}  // namespace
}  // namespace shaderport::testing

namespace shaderport::testing {
namespace {

// `--link VS FS` may be given more than once (docs/cli.md), and a file after a pair is
// checked as one more input.
TEST(CheckCliTest, LinkIsRepeatable) {
  const std::filesystem::path dir = ScratchDir("link-repeatable");
  std::ofstream(dir / "a.vert") << "attribute vec4 p;\nvarying vec2 v;\n"
                                   "void main() { v = p.xy; gl_Position = p; }\n";
  std::ofstream(dir / "a.frag") << "precision mediump float;\nvarying vec3 v;\n"
                                   "void main() { gl_FragColor = vec4(v, 1.0); }\n";
  std::ofstream(dir / "b.vert") << "attribute vec4 p;\nvarying float w;\n"
                                   "void main() { w = p.x; gl_Position = p; }\n";
  std::ofstream(dir / "b.frag") << "precision mediump float;\nvarying vec2 w;\n"
                                   "void main() { gl_FragColor = vec4(w, 0.0, 1.0); }\n";
  std::ofstream(dir / "c.frag") << "precision mediump float;\n"
                                   "void main() { gl_FragColor = vec4(1.0); }\n";
  const CommandResult both = RunShaderport(
      "check --no-config --no-cache --link a.vert a.frag --link b.vert b.frag c.frag", dir);
  EXPECT_EQ(both.exit_code, 1) << both.err;
  EXPECT_NE(both.out.find("a.frag:2:14"), std::string::npos) << both.out;
  EXPECT_NE(both.out.find("b.frag:2:14"), std::string::npos) << both.out;
  EXPECT_NE(both.out.find("(5 files checked)"), std::string::npos) << both.out;
}

// `--enabled-extensions` says which extensions the page enabled: one the context offers
// but the page did not enable leaves its functions undeclared, as in Chromium (held-out
// conformance page shader-with-dfdx.frag.html); by default every one is enabled.
TEST(CheckCliTest, EnabledExtensionsNarrowWhatThePageOffers) {
  const std::filesystem::path dir = ScratchDir("enabled-extensions");
  std::ofstream(dir / "d.frag") << "#extension GL_OES_standard_derivatives : enable\n"
                                   "precision mediump float;\nvarying vec2 v;\n"
                                   "void main() { gl_FragColor = vec4(dFdx(v), 0.0, 1.0); }\n";
  const CommandResult all = RunShaderport("check --no-config --no-cache d.frag", dir);
  EXPECT_EQ(all.exit_code, 0) << all.out << all.err;
  const CommandResult listed = RunShaderport(
      "check --no-config --no-cache --enabled-extensions "
      "GL_EXT_frag_depth,GL_OES_standard_derivatives d.frag",
      dir);
  EXPECT_EQ(listed.exit_code, 0) << listed.out << listed.err;
  for (const char* none : {"none", "GL_EXT_frag_depth"}) {
    const CommandResult off = RunShaderport(
        std::string("check --no-config --no-cache --enabled-extensions ") + none + " d.frag", dir);
    EXPECT_EQ(off.exit_code, 1) << off.out << off.err;
    EXPECT_NE(off.out.find("d.frag:1:1: warning: 'GL_OES_standard_derivatives' is not enabled by "
                           "the page"),
              std::string::npos)
        << off.out;
    EXPECT_NE(off.out.find("d.frag:4:"), std::string::npos) << off.out;  // dFdx undeclared
  }
  const CommandResult unknown = RunShaderport(
      "check --no-config --no-cache --enabled-extensions GL_OES_nonsense d.frag", dir);
  EXPECT_EQ(unknown.exit_code, 2) << unknown.out << unknown.err;
  EXPECT_NE(unknown.err.find("unknown extension 'GL_OES_nonsense'"), std::string::npos)
      << unknown.err;
}

}  // namespace
}  // namespace shaderport::testing
