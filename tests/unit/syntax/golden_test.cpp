// Golden DumpAst outputs: tests/golden/syntax/<name>.glsl -> <name>.ast.
// Regenerate with SHADERPORT_UPDATE_GOLDENS=1; never edit the .ast files by hand.
#include "golden.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "parse_helpers.h"

namespace shaderport::glsl::testing {
namespace {

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
  std::string input = shaderport::testing::ReadWholeFile(base + ".glsl");
  ASSERT_FALSE(input.empty()) << base;
  std::string actual = Render(*ParseText(input, 100));
  EXPECT_TRUE(shaderport::testing::MatchesGolden(actual, base + ".ast"));
}

INSTANTIATE_TEST_SUITE_P(Syntax, GoldenTest,
                         ::testing::Values("declarations", "statements", "webgl1", "errors"));

}  // namespace
}  // namespace shaderport::glsl::testing
