// Golden test of DumpTypes: tests/golden/sema/<name>.frag -> <name>.frag.types.
// SHADERPORT_UPDATE_GOLDENS=1 rewrites the expected files.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "golden.h"
#include "sema_test_util.h"

namespace shaderport::glsl {
namespace {

// Types, then one line per mismatch, so the golden also pins TypeMismatch.
std::string Render(const testing::Analyzed& a) {
  std::string out = DumpTypes(a.parse.tree, a.model, a.sources);
  for (const TypeMismatch& m : a.model.mismatches) {
    out += "mismatch '" + a.TextOf(m.node) + "' : " + a.model.Spell(m.actual) + " where " +
           a.model.Spell(m.required) + " is required\n";
  }
  return out;
}

TEST(DumpTypesTest, Goldens) {
  const std::filesystem::path dir =
      std::filesystem::path(SHADERPORT_SOURCE_DIR) / "tests" / "golden" / "sema";
  int cases = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".frag") continue;
    ++cases;
    auto a = testing::AnalyzeText(shaderport::testing::ReadWholeFile(entry.path()));
    std::string actual = Render(*a);
    EXPECT_TRUE(shaderport::testing::MatchesGolden(actual, entry.path().string() + ".types"));
  }
  EXPECT_GE(cases, 1);
}

TEST(DumpTypesTest, OneLinePerExpressionWithPosition) {
  auto a =
      testing::AnalyzeText("#version 300 es\nprecision highp float;\nfloat x = 1.0 +\n  2.0;\n");
  EXPECT_EQ(DumpTypes(a->parse.tree, a->model, a->sources),
            "3:11 '1.0 + 2.0' : float\n3:11 '1.0' : float\n4:3 '2.0' : float\n");
}

}  // namespace
}  // namespace shaderport::glsl
