// Golden files for DumpTokens and DumpPpTokens under tests/golden/lex/.
// Regenerate with SHADERPORT_UPDATE_GOLDENS=1; never edit them by hand.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "glsl/lex/lexer.h"
#include "golden.h"
#include "pp_test_util.h"
#include "test_corpora.h"

namespace shaderport::glsl {
namespace {

struct GoldenCase {
  const char* name;
  const char* source;
};

constexpr GoldenCase kCases[] = {
    {"numbers-and-punctuators",
     "#version 300 es\nfloat a = 1. + .5e-3 * 0x1Fu << 2; // c\nb >>= 017u; c ^^ d;\n"},
    {"macros",
     "#define SQ(x) ((x) * (x))\n#define CAT(a, b) a ## b\n#define ONE 1.0\n"
     "float v = SQ(ONE) + CAT(v, 2);\n#if defined(SQ) && __LINE__ > 3\nint line = __LINE__;\n"
     "#else\nskipped $\n#endif\n"},
    {"hostile-bytes", "a\r\nb\rc \\\nd\t/* unterminated \x01\xff"},
};

void CompareWithGolden(const std::string& file_name, const std::string& actual) {
  EXPECT_TRUE(shaderport::testing::MatchesGolden(
      actual, std::string(SHADERPORT_SOURCE_DIR) + "/tests/golden/lex/" + file_name));
}

TEST(DumpGolden, Tokens) {
  for (const GoldenCase& c : kCases) {
    const SourceFile file(0, std::string(c.name) + ".glsl", c.source);
    CompareWithGolden(std::string(c.name) + ".tokens", DumpTokens(file, Lex(file)));
  }
}

TEST(DumpGolden, PpTokens) {
  for (const GoldenCase& c : kCases) {
    auto run = testing::RunPp(c.source);
    std::string dump = DumpPpTokens(run.result, *run.sources);
    for (const auto& d : run.result.diagnostics) {
      const auto at = run.sources->Get(d.range.file).LocationOf(d.range.begin);
      dump += "diagnostic " + std::to_string(at.line) + ":" + std::to_string(at.column) + " " +
              d.rule_id + ": " + d.message + "\n";
    }
    CompareWithGolden(std::string(c.name) + ".pp-tokens", dump);
  }
}

}  // namespace
}  // namespace shaderport::glsl
