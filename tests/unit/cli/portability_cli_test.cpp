// The portability/* lint rules through the real binary: `check` reports them as
// warnings (failing only with --fail-on warning), `fix` and `port` write the zero
// values browsers use.
#include <gtest/gtest.h>

#include <fstream>

#include "cli_test_util.h"
#include "scratch_dir.h"

namespace shaderport::testing {
namespace {

namespace fs = std::filesystem;

fs::path TempDir(const std::string& name) { return ScratchDir("portability-" + name); }

void Write(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

constexpr const char* kGolf =
    "void mainImage(out vec4 O, in vec2 U) {\n"
    "  vec4 col2;\n"
    "  col2 += vec4(0.5);\n"
    "  vec3 col = vec3(0.0);\n"
    "  for (int c = 0; c < 8; c++) col[c] = 0.1 * float(c);\n"
    "  O += col2 + vec4(col, 1.0);\n"
    "}\n";

TEST(PortabilityCli, CheckReportsBothRulesAsWarnings) {
  const fs::path dir = TempDir("check");
  Write(dir / "golf.glsl", kGolf);
  const CommandResult result = RunShaderport("check --no-config golf.glsl", dir);
  EXPECT_EQ(result.exit_code, 0) << result.out << result.err;
  EXPECT_NE(result.out.find("golf.glsl:3:3: warning: [*] 'col2' may be read before it is written: "
                            "browsers start it at 0, native GL, Vulkan and Metal leave it "
                            "undefined [portability/uninitialized-read]"),
            std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("golf.glsl:6:3: warning: [*] 'O' (an out parameter) may be read"),
            std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("golf.glsl:5:35: warning: index 'c' runs 0..7 here but 'col' (vec3) "
                            "has 3 components: browsers clamp it to 0..2 (col[2] is written "
                            "instead), native targets write out of bounds "
                            "[portability/index-range]"),
            std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("0 errors, 3 warnings"), std::string::npos) << result.out;

  const CommandResult strict = RunShaderport("check --no-config --fail-on warning golf.glsl", dir);
  EXPECT_EQ(strict.exit_code, 1) << strict.out << strict.err;

  const CommandResult json = RunShaderport("check --no-config --format json golf.glsl", dir);
  EXPECT_NE(json.out.find("\"rule\": \"portability/uninitialized-read\""), std::string::npos)
      << json.out;
  EXPECT_NE(json.out.find("\"rule\": \"portability/index-range\""), std::string::npos);
}

TEST(PortabilityCli, ConfigurationCanTurnTheRulesOff) {
  const fs::path dir = TempDir("config");
  Write(dir / "golf.glsl", kGolf);
  Write(dir / ".shaderport.toml", "[rules]\n\"portability/*\" = \"off\"\n");
  const CommandResult result = RunShaderport("check --fail-on warning golf.glsl", dir);
  EXPECT_EQ(result.exit_code, 0) << result.out << result.err;
  EXPECT_EQ(result.out.find("portability/"), std::string::npos) << result.out;
}

TEST(PortabilityCli, FixAndPortWriteTheBrowsersZeros) {
  const fs::path dir = TempDir("fix");
  Write(dir / "toy.glsl",
        "void mainImage(out vec4 O, in vec2 U) {\n"
        "  vec4 col2;\n"
        "  col2 += vec4(0.5);\n"
        "  O += col2;\n"
        "}\n");
  const CommandResult fixed = RunShaderport("fix toy.glsl", dir);
  EXPECT_EQ(fixed.exit_code, 0) << fixed.err;
  EXPECT_EQ(fixed.out,
            "void mainImage(out vec4 O, in vec2 U) {\n"
            "  O = vec4(0.0);\n"
            "  vec4 col2 = vec4(0.0);\n"
            "  col2 += vec4(0.5);\n"
            "  O += col2;\n"
            "}\n");

  const CommandResult ported = RunShaderport("port toy.glsl", dir);
  EXPECT_EQ(ported.exit_code, 0) << ported.err;
  EXPECT_NE(ported.out.find("#version 300 es"), std::string::npos) << ported.out;
  EXPECT_NE(ported.out.find("void mainImage(out vec4 O, in vec2 U) {\n"
                            "  O = vec4(0.0);\n"
                            "  vec4 col2 = vec4(0.0);\n"),
            std::string::npos)
      << ported.out;
}

// An index out of range has no fix: the finding is left, as every unfixed finding is.
TEST(PortabilityCli, FixLeavesTheIndexToTheAuthor) {
  const fs::path dir = TempDir("index");
  Write(dir / "golf.glsl", kGolf);
  const CommandResult fixed = RunShaderport("fix golf.glsl", dir);
  // The index warning no fix repairs does not fail fix unless --fail-on warning.
  EXPECT_EQ(fixed.exit_code, 0) << fixed.err;
  EXPECT_EQ(RunShaderport("fix --fail-on warning golf.glsl", dir).exit_code, 1);
  EXPECT_NE(fixed.out.find("  vec4 col2 = vec4(0.0);\n"), std::string::npos) << fixed.out;
  EXPECT_NE(fixed.out.find("col[c] = 0.1"), std::string::npos) << fixed.out;
  EXPECT_NE(fixed.err.find("golf.glsl:5:35: warning: index 'c' runs 0..7"), std::string::npos)
      << fixed.err;
  EXPECT_EQ(fixed.err.find("uninitialized-read"), std::string::npos) << fixed.err;
}

}  // namespace
}  // namespace shaderport::testing
