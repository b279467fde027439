// End to end: the ShaderToy shaders of corpus/ (ao/, strict-typing/) and the
// raymarching blog's four listings port to GLSL ES 3.00 that glslang accepts,
// and porting the result again changes nothing.
#include <gtest/gtest.h>

#include "shadertoy_test_support.h"

namespace shaderport::shadertoy_test {
namespace {

namespace fs = std::filesystem;

struct Row {
  std::string path;
  std::string dialect;
  std::string expect;
};

// corpus/MANIFEST: tab-separated path, origin, dialect, stage, expect.
std::vector<Row> Manifest() {
  const std::string text =
      shaderport::testing::ReadWholeFile(fs::path(SHADERPORT_SOURCE_DIR) / "corpus" / "MANIFEST");
  std::vector<Row> rows;
  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line);  // header
  while (std::getline(lines, line)) {
    std::vector<std::string> fields;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, '\t')) fields.push_back(cell);
    if (fields.size() >= 5) rows.push_back({fields[0], fields[2], fields[4]});
  }
  return rows;
}

void ExpectPorts(const Row& row, const char* dialect_name) {
  SCOPED_TRACE(row.path);
  const std::string text =
      shaderport::testing::ReadWholeFile(fs::path(SHADERPORT_SOURCE_DIR) / "corpus" / row.path);
  const rule::PortSettings settings = HarnessSettings(model::FindBuiltinDialect(dialect_name));
  ASSERT_NE(settings.harness, nullptr);
  const rule::FixEngineResult ported = Port(text, settings);
  EXPECT_TRUE(ported.converged);
  const auto compiled = CompileEssl300(ported.text);
  EXPECT_TRUE(compiled.Accepted(true)) << Messages(compiled) << ported.text;
  EXPECT_EQ(Port(ported.text, settings).text, ported.text) << "porting twice changed the text";
}

TEST(ShadertoyCorpus, ShaderToyShadersPort) {
  int count = 0;
  for (const Row& row : Manifest()) {
    if (row.dialect != "shadertoy" || row.expect.starts_with("seed-error")) continue;
    ExpectPorts(row, "shadertoy");
    ++count;
  }
  EXPECT_GE(count, 20);  // 7 ao/ + 15 strict-typing/ .glsl files
}

TEST(ShadertoyCorpus, RaymarchBlogListingsPortWithTheirDialect) {
  int count = 0;
  for (const Row& row : Manifest()) {
    if (row.dialect != "raymarch-harness") continue;
    ExpectPorts(row, "raymarch-blog");
    ++count;
  }
  EXPECT_EQ(count, 4);
}

}  // namespace
}  // namespace shaderport::shadertoy_test
