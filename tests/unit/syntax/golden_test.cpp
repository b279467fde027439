// Golden DumpAst outputs: tests/golden/syntax/<name>.glsl -> <name>.ast.
// Regenerate with SHADERPORT_UPDATE_GOLDENS=1; never edit the .ast files by hand.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "parse_helpers.h"

namespace shaderport::glsl::testing {
namespace {

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The dump followed by the diagnostics, one a line.
std::string Render(const Parsed& parsed) {
  std::string out = parsed.Dump();
  for (const auto& d : parsed.result.diagnostics) {
    LineColumn at = parsed.sources.Get(d.range.file).LocationOf(d.range.begin);
    out += std::to_string(at.line) + ":" + std::to_string(at.column) + ": " +
           SeverityName(d.severity) + ": " + d.message + " [" + d.rule_id + "]\n";
  }
  return out;
}

class GoldenTest : public ::testing::TestWithParam<const char*> {};

TEST_P(GoldenTest, DumpMatches) {
  std::string base = std::string(SHADERPORT_SOURCE_DIR) + "/tests/golden/syntax/" + GetParam();
  std::string input = ReadFile(base + ".glsl");
  ASSERT_FALSE(input.empty()) << base;
  std::string actual = Render(*ParseText(input, 100));
  const char* update = std::getenv("SHADERPORT_UPDATE_GOLDENS");
  if (update != nullptr && std::string(update) == "1") {
    std::ofstream(base + ".ast", std::ios::binary) << actual;
    GTEST_SKIP() << "updated " << base << ".ast";
  }
  EXPECT_EQ(actual, ReadFile(base + ".ast")) << "regenerate with SHADERPORT_UPDATE_GOLDENS=1";
}

INSTANTIATE_TEST_SUITE_P(Syntax, GoldenTest,
                         ::testing::Values("declarations", "statements", "webgl1", "errors"));

}  // namespace
}  // namespace shaderport::glsl::testing
