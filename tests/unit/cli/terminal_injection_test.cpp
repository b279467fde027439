// Control characters in names and ids that come from files (a file name, a JSON
// pass name, a .shaderport.toml key, a suppression id) are escaped in text output:
// no escape sequence reaches the terminal and a newline cannot forge a finding line.
#include <gtest/gtest.h>

#include <string>

#include "cli/cli_test_util.h"
#include "cli/temp_project.h"

namespace shaderport::testing {
namespace {

constexpr const char* kForged = "fake.glsl:1:1: error: INJECTED";

// No byte below 0x20 but the newlines ending lines, and no forged line.
void ExpectPrintable(const std::string& output, const std::string& what) {
  for (const char c : output) {
    const auto byte = static_cast<unsigned char>(c);
    ASSERT_FALSE((byte < 0x20 && byte != '\n') || byte == 0x7F)
        << what << ": control byte " << int{byte} << " in\n"
        << output;
  }
  EXPECT_EQ(output.find("\n" + std::string(kForged)), std::string::npos) << what << output;
  EXPECT_NE(output.rfind(kForged, 0), 0u) << what << output;
}

TEST(TerminalInjectionCli, PassNameCannotForgeAFindingLine) {
  TempProject project("inject-pass");
  // A pass name with a newline, an escape sequence and a forged finding after it.
  project.Write(
      "p.json",
      R"({"id":"x","passes":[{"type":"image","name":"Image\n)" + std::string(kForged) +
          R"(\u001b[2J","code":"void mainImage(out vec4 c, in vec2 p) { c = vec4(1); }\nint x = 1.0;\n"}]})");
  const CommandResult result = RunShaderport("check --no-cache p.json", project.Root());
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_NE(result.out.find("\\n" + std::string(kForged) + "\\x1b[2J"), std::string::npos)
      << result.out;
  ExpectPrintable(result.out, "check");
  const CommandResult port = RunShaderport("port --out-dir out p.json", project.Root());
  ExpectPrintable(port.err, "port");
}

TEST(TerminalInjectionCli, FileNamesConfigKeysAndSuppressionIdsAreEscaped) {
  TempProject project("inject-names");
  const std::string name = "a\x1b[31m\n" + std::string(kForged) + ".frag";
  project.Write(name,
                "#version 300 es\nprecision mediump float;\nout vec4 o;\n"
                "void main() { float x = 1; o = vec4(x); } // shaderport-disable-line "
                "bad\x1b[2Jid\n");
  project.Write(".shaderport.toml", "[check]\n\"key\x1b]0;title\x07\" = 1\n");
  const CommandResult result = RunShaderport("check --no-cache .", project.Root());
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_NE(result.out.find("a\\x1b[31m\\n"), std::string::npos) << result.out;
  ExpectPrintable(result.out, "check stdout");
  ExpectPrintable(result.err, "check stderr");
  const CommandResult missing = RunShaderport("check 'gone\x1b[2J'", project.Root());
  EXPECT_EQ(missing.exit_code, 2);
  ExpectPrintable(missing.err, "usage error");
}

}  // namespace
}  // namespace shaderport::testing
