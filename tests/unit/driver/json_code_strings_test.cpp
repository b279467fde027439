#include "driver/project/json_code_strings.h"

#include <gtest/gtest.h>

#include "driver/project/json_code_rewrite.h"
#include "driver/project/json_project_reader.h"

namespace shaderport::driver::project {
namespace {

TEST(JsonCodeStrings, FindsCodeValuesByPointerAndIgnoresKeysAndOtherMembers) {
  const std::string json =
      R"({"code": "top", "a": [{"code": "x"}, {"name": "code", "code": "y"}], "b": {"c~/d": {"code": ""}}})";
  const auto found = FindStringValues(json, "code");
  ASSERT_EQ(found.size(), 4u);
  EXPECT_EQ(json.substr(found.at("/code").begin, 5), "\"top\"");
  EXPECT_EQ(json.substr(found.at("/a/0/code").begin, 3), "\"x\"");
  EXPECT_EQ(json.substr(found.at("/a/1/code").begin, 3), "\"y\"");
  EXPECT_TRUE(found.contains("/b/c~0~1d/code"));
}

TEST(JsonCodeStrings, DecodesEscapesAndMapsEveryByteToItsDocumentOffset) {
  const std::string json = R"({"code": "a\nb\u00e9\ud83d\ude00\"\/"})";
  const JsonLiteral literal = FindStringValues(json, "code").at("/code");
  const DecodedString decoded = DecodeWithOffsets(json, literal);
  EXPECT_EQ(decoded.text, "a\nb\xC3\xA9\xF0\x9F\x98\x80\"/");
  ASSERT_EQ(decoded.offsets.size(), decoded.text.size() + 1);
  EXPECT_EQ(json[decoded.offsets[0]], 'a');
  EXPECT_EQ(json.substr(decoded.offsets[1], 2), "\\n");
  EXPECT_EQ(json[decoded.offsets[2]], 'b');
  EXPECT_EQ(json.substr(decoded.offsets[3], 6), "\\u00e9");
  EXPECT_EQ(decoded.offsets[4], decoded.offsets[3]);  // both bytes of é
  EXPECT_EQ(json.substr(decoded.offsets[5], 12), "\\ud83d\\ude00");
  EXPECT_EQ(json[decoded.offsets.back()], '"');
}

TEST(JsonCodeStrings, EncodesWhatJsonRequiresAndNothingElse) {
  EXPECT_EQ(EncodeJsonString("a\"b\\c\n\t\x01/é"), "\"a\\\"b\\\\c\\n\\t\\u0001/é\"");
}

TEST(JsonCodeRewrite, ReplacesOnlyCodeStringsAndKeepsKeptBytesSpelledAsBefore) {
  const std::string json =
      "{\"Shader\": {\"info\": {\"name\": \"x\"},\n \"renderpass\": [{\"type\": \"image\", "
      "\"name\": \"Image\", \"code\": \"// \\u00e9\\/\\nvec3 v = 1.0;\\n\", \"inputs\": []}]}}";
  const ProjectDocument read = ReadShaderToyJson(json);
  ASSERT_TRUE(read.problems.empty());
  const ProjectPass& pass = read.projects.at(0).passes.at(0);
  // The fix inserts "vec3(" and ")" around 1.0.
  const std::string code = pass.code;
  const auto at = static_cast<uint32_t>(code.find("1.0"));
  SourceMap map;
  map.Append({0, at, 0, at, false});
  map.Append({at, 5, at, at, true});
  map.Append({at + 5, 3, at, at + 3, false});
  map.Append({at + 8, 1, at + 3, at + 3, true});
  const auto rest = static_cast<uint32_t>(code.size()) - (at + 3);
  map.Append({at + 9, rest, at + 3, at + 3 + rest, false});
  const std::string fixed = code.substr(0, at) + "vec3(1.0)" + code.substr(at + 3);
  map.SetSizes(static_cast<uint32_t>(code.size()), static_cast<uint32_t>(fixed.size()));
  const std::string rewritten = RewriteCodeStrings(json, {{&pass, fixed, &map}});
  EXPECT_EQ(rewritten,
            "{\"Shader\": {\"info\": {\"name\": \"x\"},\n \"renderpass\": [{\"type\": \"image\", "
            "\"name\": \"Image\", \"code\": \"// \\u00e9\\/\\nvec3 v = vec3(1.0);\\n\", "
            "\"inputs\": []}]}}");
  EXPECT_EQ(ReadShaderToyJson(rewritten).projects.at(0).passes.at(0).code, fixed);
}

}  // namespace
}  // namespace shaderport::driver::project
