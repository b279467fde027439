// Loading harness dialects from TOML: the shipped files, and broken files whose
// errors must come with a line and column.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "model/harness_dialect.h"
#include "model/shipped_dialects.h"
#include "rule/harness_dialect_file.h"

namespace shaderport::rule {
namespace {

using model::DeclarationOf;
using model::DeclareMode;
using model::HarnessDialect;
using model::ProvidedStorage;

DialectLoadResult Parse(std::string text) {
  static std::vector<std::unique_ptr<SourceFile>> files;  // keep text alive for ranges
  files.push_back(std::make_unique<SourceFile>(7, "test.toml", std::move(text)));
  return ParseDialect(*files.back());
}

// "rule line:col" of each diagnostic.
std::vector<std::string> Where(const DialectLoadResult& result, const std::string& text) {
  const SourceFile file(7, "test.toml", text);
  std::vector<std::string> out;
  for (const Diagnostic& d : result.diagnostics) {
    const LineColumn at = file.LocationOf(d.range.begin);
    out.push_back(d.rule_id + " " + std::to_string(at.line) + ":" + std::to_string(at.column));
  }
  return out;
}

TEST(DialectToml, ShippedDialectsLoadWithoutDiagnostics) {
  const auto dialects = model::BuiltinDialects();
  // Every file of rules/dialects/ is built in, sorted by name, and loads cleanly.
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(
           std::filesystem::path(SHADERPORT_SOURCE_DIR) / "rules" / "dialects")) {
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_EQ(dialects.size(), files.size());
  EXPECT_EQ(dialects[0].name, "bookofshaders");
  EXPECT_NE(model::FindBuiltinDialect("shadertoy"), nullptr);
  SourceManager sources;
  for (const std::filesystem::path& path : files) {
    const std::string file = path.filename().string();
    const auto loaded = LoadDialect(path.string(), sources);
    EXPECT_TRUE(loaded.dialect.has_value()) << file;
    EXPECT_TRUE(loaded.diagnostics.empty()) << file << ": " << loaded.diagnostics[0].message;
  }
}

TEST(DialectToml, ShaderToyProvidesTheSiteUniformsInOrder) {
  const HarnessDialect* shadertoy = model::FindBuiltinDialect("shadertoy");
  ASSERT_NE(shadertoy, nullptr);
  std::vector<std::string> declarations;
  for (const auto& v : shadertoy->provides) declarations.push_back(DeclarationOf(v));
  const std::vector<std::string> expected = {"uniform highp vec3 iResolution;",
                                             "uniform highp float iTime;",
                                             "uniform highp float iChannelTime[4];",
                                             "uniform highp vec4 iMouse;",
                                             "uniform highp vec4 iDate;",
                                             "uniform highp float iSampleRate;",
                                             "uniform highp vec3 iChannelResolution[4];",
                                             "uniform highp int iFrame;",
                                             "uniform highp float iTimeDelta;",
                                             "uniform highp float iFrameRate;",
                                             "uniform sampler2D iChannel0;",
                                             "uniform sampler2D iChannel1;",
                                             "uniform sampler2D iChannel2;",
                                             "uniform sampler2D iChannel3;"};
  EXPECT_EQ(declarations, expected);
  EXPECT_EQ(shadertoy->defines, std::vector<std::string>{"HW_PERFORMANCE 1"});
  ASSERT_EQ(shadertoy->entry_points.size(), 3u);
  EXPECT_EQ(shadertoy->entry_points[0].function, "mainImage");
  EXPECT_EQ(shadertoy->entry_points[1].function, "mainCubemap");
  EXPECT_EQ(shadertoy->entry_points[2].function, "mainSound");
  ASSERT_EQ(shadertoy->renames.size(), 1u);
  EXPECT_EQ(shadertoy->renames[0].first, "iGlobalTime");
  EXPECT_EQ(shadertoy->renames[0].second, "iTime");
  EXPECT_EQ(shadertoy->declare, DeclareMode::kAll);
}

TEST(DialectToml, AliasesFindDialects) {
  ASSERT_NE(model::FindBuiltinDialect("raymarch-harness"), nullptr);
  EXPECT_EQ(model::FindBuiltinDialect("raymarch-harness")->name, "raymarch-blog");
  EXPECT_EQ(model::FindBuiltinDialect("glslcanvas")->name, "bookofshaders");
  EXPECT_EQ(model::FindBuiltinDialect("nope"), nullptr);
}

TEST(DialectToml, DeclarationSpellings) {
  EXPECT_EQ(DeclarationOf({"uv", "vec2", ProvidedStorage::kInput, "", -1}), "in highp vec2 uv;");
  EXPECT_EQ(DeclarationOf({"color", "vec4", ProvidedStorage::kOutput, "mediump", -1}),
            "out mediump vec4 color;");
  EXPECT_EQ(
      DeclarationOf({"iChannel0", "sampler2D", ProvidedStorage::kUniform, "", 0}, "sampler3D"),
      "uniform mediump sampler3D iChannel0;");
}

TEST(DialectToml, UserDialectWithEntryPoint) {
  const auto result = Parse(R"(name = "mine"
declare = "all"
defines = ["FOO", "BAR 2"]
renames = { oldTime = "t" }
[[provides]]
name = "t"
type = "float"
[[entry_points]]
function = "render"
output = "outColor"
main = "vec4 {fresh:c};\n{entry}({fresh:c});\n{out} = {fresh:c};"
)");
  ASSERT_TRUE(result.dialect) << (result.diagnostics.empty() ? "" : result.diagnostics[0].message);
  EXPECT_TRUE(result.diagnostics.empty());
  EXPECT_EQ(result.dialect->entry_points[0].output_name, "outColor");
  EXPECT_EQ(result.dialect->defines.size(), 2u);
}

TEST(DialectToml, SyntaxErrorHasLineAndColumn) {
  const std::string text = "name = \"x\"\n[[provides]]\nname = = 3\n";
  const auto result = Parse(text);
  EXPECT_FALSE(result.dialect);
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].rule_id, "dialect/syntax-error");
  EXPECT_EQ(Where(result, text)[0].substr(0, 22), "dialect/syntax-error 3");
}

TEST(DialectToml, BadValuesAreLocated) {
  const std::string text =
      "name = \"x\"\n"
      "declare = \"some\"\n"
      "colour = 1\n"
      "[[provides]]\n"
      "name = \"a b\"\n"
      "type = \"vec3\"\n"
      "[[provides]]\n"
      "name = \"t\"\n"
      "type = \"vec9\"\n"
      "[[provides]]\n"
      "name = \"c\"\n"
      "type = \"float\"\n"
      "channel = 7\n";
  const auto result = Parse(text);
  EXPECT_FALSE(result.dialect);
  const std::vector<std::string> expected = {
      "dialect/invalid-value 2:11", "dialect/unknown-key 3:1", "dialect/invalid-value 5:8",
      "dialect/invalid-value 9:8", "dialect/invalid-value 13:11"};
  auto where = Where(result, text);
  std::sort(where.begin(), where.end());
  auto sorted = expected;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(where, sorted);
}

TEST(DialectToml, MissingNameAndUnknownPlaceholder) {
  const auto result = Parse(
      "[[entry_points]]\nfunction = \"f\"\nmain = \"{entry}(); {outt} = vec4(1.0); if (x) { }\"\n");
  EXPECT_FALSE(result.dialect);
  std::vector<std::string> messages;
  for (const auto& d : result.diagnostics) messages.push_back(d.rule_id + ": " + d.message);
  ASSERT_EQ(messages.size(), 2u);
  EXPECT_NE(messages[0].find("unknown placeholder '{outt}'"), std::string::npos) << messages[0];
  EXPECT_EQ(messages[1], "dialect/missing-key: the dialect has no 'name'");
}

TEST(DialectToml, DuplicatesAndWrongShapes) {
  const auto result = Parse(
      "name = \"x\"\nprovides = 3\nhints = [1]\nrenames = { \"a b\" = \"c\" }\n"
      "defines = [\"1X\"]\n");
  EXPECT_FALSE(result.dialect);
  EXPECT_EQ(result.diagnostics.size(), 4u);
  const auto dup = Parse(
      "name = \"x\"\n[[provides]]\nname = \"t\"\ntype = \"float\"\n[[provides]]\nname = \"t\"\n"
      "type = \"int\"\n");
  ASSERT_EQ(dup.diagnostics.size(), 1u);
  EXPECT_NE(dup.diagnostics[0].message.find("provided twice"), std::string::npos);
}

TEST(DialectToml, UnknownDialectNameOrFile) {
  SourceManager sources;
  const auto result = LoadDialect("/no/such/dialect.toml", sources);
  EXPECT_FALSE(result.dialect);
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].rule_id, "dialect/not-found");
  EXPECT_TRUE(LoadDialect("shadertoy", sources).dialect.has_value());
}

TEST(DialectToml, HugeOrBinaryInputDoesNotCrash) {
  EXPECT_FALSE(Parse(std::string(2u << 20, 'a')).dialect);
  EXPECT_FALSE(Parse(std::string("\0\xff\xfe[[[", 7)).dialect);
  EXPECT_FALSE(Parse(std::string(5000, '[')).dialect);
}

}  // namespace
}  // namespace shaderport::rule
