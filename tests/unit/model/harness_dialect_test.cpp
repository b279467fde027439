// The harness model reads its dialects without the layers above it: the shipped
// table, and problems located by byte in the TOML text.
#include "model/harness_dialect.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "model/shipped_dialects.h"

namespace shaderport::model {
namespace {

// Every file of rules/dialects/, so that a new dialect is that file and its test.
size_t ShippedDialectFiles() {
  size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(
           std::filesystem::path(SHADERPORT_SOURCE_DIR) / "rules" / "dialects")) {
    files += entry.path().extension() == ".toml";
  }
  return files;
}

TEST(HarnessDialect, ShippedDialectsAllLoad) {
  // A shipped file with errors would be left out of the table.
  ASSERT_GE(ShippedDialectFiles(), 4u);
  ASSERT_EQ(BuiltinDialects().size(), ShippedDialectFiles());
  EXPECT_EQ(&ShaderToyDialect(), FindBuiltinDialect("shadertoy"));
  EXPECT_EQ(ShaderToyDialect().declare, DeclareMode::kAll);
}

TEST(HarnessDialect, SiteUniformsAreTheNonChannelUniformsInOrder) {
  std::vector<std::string> names;
  for (const ProvidedVariable* v : ShaderToySiteUniforms()) names.push_back(v->name);
  EXPECT_EQ(names, (std::vector<std::string>{"iResolution", "iTime", "iChannelTime", "iMouse",
                                             "iDate", "iSampleRate", "iChannelResolution", "iFrame",
                                             "iTimeDelta", "iFrameRate"}));
}

TEST(HarnessDialect, ProblemsAreByteRangesInTextOrder) {
  // "é" is two bytes: toml++'s character column becomes a byte offset.
  const std::string text = "name = \"x\"\n# é\nbogus = 1\ndeclare = \"é\"\n";
  const DialectParse parsed = ParseDialect(text, "x.toml");
  EXPECT_FALSE(parsed.dialect.has_value());
  ASSERT_EQ(parsed.problems.size(), 2u);
  EXPECT_FALSE(parsed.problems[0].error);
  EXPECT_EQ(parsed.problems[0].rule_id, "dialect/unknown-key");
  EXPECT_EQ(text.substr(parsed.problems[0].begin, 5), "bogus");
  EXPECT_TRUE(parsed.problems[1].error);
  EXPECT_EQ(
      text.substr(parsed.problems[1].begin, parsed.problems[1].end - parsed.problems[1].begin),
      "\"é\"");
}

TEST(HarnessDialect, DeclarationLeavesPrecisionToTheHeaderWhenAsked) {
  const ProvidedVariable resolution{"iResolution", "vec3", ProvidedStorage::kUniform, "", -1};
  EXPECT_EQ(DeclarationOf(resolution), "uniform highp vec3 iResolution;");
  EXPECT_EQ(DeclarationOf(resolution, {}, PrecisionSpelling::kOmitted),
            "uniform vec3 iResolution;");
  const ProvidedVariable times{"iChannelTime", "float[4]", ProvidedStorage::kUniform, "mediump",
                               -1};
  EXPECT_EQ(DeclarationOf(times, {}, PrecisionSpelling::kOmitted),
            "uniform mediump float iChannelTime[4];");
}

}  // namespace
}  // namespace shaderport::model
