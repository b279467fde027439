#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "cli/cli_test_util.h"
#include "scratch_dir.h"

namespace shaderport::testing {
namespace {

namespace fs = std::filesystem;

constexpr const char* kWebGL1 =
    "precision mediump float;\nvarying vec2 uv;\nuniform sampler2D tex;\n"
    "void main() {\n  gl_FragColor = texture2D(tex, uv);\n}\n";

fs::path TempDir(const std::string& name) { return ScratchDir("port-" + name); }

void Write(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

TEST(PortCli, PortsWebGL1ToEssl300AndIsIdempotent) {
  const fs::path dir = TempDir("idem");
  Write(dir / "a.frag", kWebGL1);
  const CommandResult once = RunShaderport("port a.frag", dir);
  ASSERT_EQ(once.exit_code, 0) << once.err;
  EXPECT_EQ(once.out.rfind("#version 300 es\n", 0), 0u) << once.out;
  EXPECT_EQ(once.out.find("gl_FragColor"), std::string::npos);
  Write(dir / "b.frag", once.out);
  const CommandResult twice = RunShaderport("port b.frag", dir);
  EXPECT_EQ(twice.exit_code, 0) << twice.err;
  EXPECT_EQ(twice.out, once.out);
}

TEST(PortCli, OutDirKeepsRelativeNamesAndStageExtension) {
  const fs::path dir = TempDir("outdir");
  fs::create_directories(dir / "sub");
  Write(dir / "sub" / "a.glsl", kWebGL1);
  // A file named alone is laid out below its own directory (the common root).
  const CommandResult result = RunShaderport("port --out-dir out sub/a.glsl", dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(fs::exists(dir / "out" / "a.frag"));
}

TEST(PortCli, UsageErrorsExitTwo) {
  const fs::path dir = TempDir("usage");
  Write(dir / "a.frag", kWebGL1);
  EXPECT_EQ(RunShaderport("port --channel 7=2d a.frag", dir).exit_code, 2);
  EXPECT_EQ(RunShaderport("port --emit nonsense a.frag", dir).exit_code, 2);
  EXPECT_EQ(RunShaderport("port --dialect nosuchdialect a.frag", dir).exit_code, 2);
  EXPECT_EQ(RunShaderport("explain no/such-rule", dir).exit_code, 2);
}

TEST(FixCli, DiffAndInPlace) {
  const fs::path dir = TempDir("fix");
  // An int literal where a float is needed: a kAlways typing rule's job.
  const std::string text =
      "#version 300 es\nprecision mediump float;\nout vec4 o;\n"
      "void main() { float x = 1; o = vec4(x); }\n";
  Write(dir / "a.frag", text);
  const CommandResult diff = RunShaderport("fix --diff a.frag", dir);
  EXPECT_NE(diff.exit_code, 3) << diff.err;
  if (!diff.out.empty()) {
    EXPECT_EQ(diff.out.rfind("--- a/a.frag\n+++ b/a.frag\n@@ ", 0), 0u) << diff.out;
  }
  const CommandResult stdout_result = RunShaderport("fix a.frag", dir);
  const CommandResult in_place = RunShaderport("fix --in-place a.frag", dir);
  EXPECT_NE(in_place.exit_code, 3) << in_place.err;
  EXPECT_EQ(ReadWholeFile(dir / "a.frag"), stdout_result.out);
}

// A failed write is forced with a file-size limit of 0 (every write fails with
// EFBIG), which holds for root too, unlike directory permissions.
TEST(FixCli, InPlaceWriteFailureLeavesOriginalAndNoTemporaryFile) {
  const fs::path dir = TempDir("nowrite");
  Write(dir / "a.frag", "void main() { float x = 1; gl_FragColor = vec4(x); }\n");
  const std::string before = ReadWholeFile(dir / "a.frag");
  const CommandResult result =
      RunShaderport("fix --in-place a.frag", dir,
                    "NO_COLOR=1 sh -c 'trap \"\" XFSZ; ulimit -f 0; exec \"$0\" \"$@\"'");
  EXPECT_NE(result.exit_code, 0) << result.err;
  EXPECT_EQ(ReadWholeFile(dir / "a.frag"), before);
  size_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u) << "a temporary file was left behind";
  const CommandResult fixed = RunShaderport("fix a.frag", dir);
  EXPECT_NE(fixed.out, before) << "the fix must change something for this test to mean anything";
}

// `fix` takes the same --dialect/--channel/--stage as `port`.
TEST(FixCli, DialectChannelAndStageOptions) {
  const fs::path dir = TempDir("fix-options");
  // Code with no mainImage is not detected as ShaderToy: read as WebGL1, iTime is
  // undeclared and nothing is fixed; told it is ShaderToy, the int literal is.
  Write(dir / "wave.glsl", "float wave() { return sin(iTime * 2); }\n");
  const CommandResult plain = RunShaderport("fix wave.glsl", dir);
  EXPECT_EQ(plain.out.find("iTime * 2.0"), std::string::npos) << plain.out;
  const CommandResult told = RunShaderport("fix --dialect shadertoy wave.glsl", dir);
  EXPECT_NE(told.out.find("iTime * 2.0"), std::string::npos) << told.out << told.err;
  EXPECT_EQ(RunShaderport("fix --dialect no-such-dialect wave.glsl", dir).exit_code, 2);
  EXPECT_EQ(RunShaderport("fix --channel 7=cube wave.glsl", dir).exit_code, 2);
  EXPECT_EQ(RunShaderport("fix --stage sideways wave.glsl", dir).exit_code, 2);
}

TEST(RulesCli, DocsRulesMdIsTheOutputOfRules) {
  const CommandResult result = RunShaderport("rules", SHADERPORT_SOURCE_DIR);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(MatchesGolden(result.out, fs::path(SHADERPORT_SOURCE_DIR) / "docs" / "rules.md"));
}

TEST(RulesCli, ExplainPrintsRulesAndCatalogEntries) {
  const CommandResult rule = RunShaderport("explain port/version", SHADERPORT_SOURCE_DIR);
  EXPECT_EQ(rule.exit_code, 0);
  EXPECT_NE(rule.out.find("## port/version"), std::string::npos);
  const CommandResult entry = RunShaderport("explain internal/error", SHADERPORT_SOURCE_DIR);
  EXPECT_EQ(entry.exit_code, 0);
  EXPECT_NE(entry.out.find("internal/error"), std::string::npos);
}

// Native targets do not zero-initialise or clamp as browsers do: the SPIR-V leg
// compiles the port with both written out (docs/browser-divergence.md).
TEST(PortCli, SpirvLegKeepsTheBrowsersInitialisationAndClamping) {
  const fs::path dir = TempDir("semantics");
  Write(dir / "golf.glsl",
        "void mainImage(out vec4 O, in vec2 U) {\n"
        "  vec4 c;\n"
        "  c += vec4(0.5);\n"
        "  vec3 col = vec3(0);\n"
        "  col[int(U.x) / 9] = 1.0;\n"
        "  O = c + vec4(col, 0.0);\n"
        "}\n");
  const CommandResult result = RunShaderport("port --emit essl-roundtrip golf.glsl", dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("vec4 c = vec4(0.0);"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find(", 0, 2)] = 1.0;"), std::string::npos) << result.out;
  // The WebGL2 port itself stays as the user wrote it: the browser does this.
  const CommandResult plain = RunShaderport("port golf.glsl", dir);
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(plain.out.find("clamp("), std::string::npos) << plain.out;
}

}  // namespace
}  // namespace shaderport::testing

namespace shaderport::testing {
namespace {

// A rename inside a macro body that misses a use breaks the ported text; narrowing
// used to rebuild the fix set from nothing, where #version alone (without the
// uniforms and main() it needs) fails too, and dropped every port fix. Now only the
// breaking fix goes.
TEST(PortCli, NarrowingDropsOnlyTheFixThatBreaksTheOutput) {
  const fs::path dir = TempDir("narrow");
  Write(dir / "toy.glsl",
        "#define render() \\\nvoid mainImage(out vec4 c, in vec2 p) {\\\n"
        "  vec2 dFdx = dFdx(p / 16.0), dFdy = dFdy(p);\\\n  vec2 d = dFdx;\\\n"
        "  c = vec4(d, 0.0, 1.0);\\\n}\nrender()\n");
  const CommandResult result = RunShaderport("port toy.glsl -o out.frag", dir);
  EXPECT_LE(result.exit_code, 1) << result.err;
  const std::string ported = ReadWholeFile(dir / "out.frag");
  EXPECT_EQ(ported.rfind("#version 300 es\n", 0), 0u) << ported;
  const std::string command = "glslangValidator '" + (dir / "out.frag").string() + "' >/dev/null";
  EXPECT_EQ(std::system(command.c_str()), 0) << ported;
}

}  // namespace
}  // namespace shaderport::testing

namespace shaderport::testing {
namespace {

// A replaced line reads as diff(1) and git print it: the old line, then the new one.
TEST(FixCli, DiffPrintsRemovedLinesBeforeTheirReplacements) {
  const fs::path dir = TempDir("diff-order");
  Write(dir / "a.frag",
        "#version 300 es\nprecision mediump float;\nout vec4 o;\n"
        "void main() {\n  float x = 1;\n  o = vec4(x);\n}\n");
  const CommandResult diff = RunShaderport("fix --diff a.frag", dir);
  EXPECT_NE(diff.out.find("\n-  float x = 1;\n+  float x = 1.0;\n"), std::string::npos) << diff.out;
}

}  // namespace
}  // namespace shaderport::testing
