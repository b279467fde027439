// Inserted statements read as if a person wrote them: on their own line with the
// block's indentation when the brace ends (or starts) its line, inline otherwise.
#include "diag/statement_insertion.h"

#include <gtest/gtest.h>

#include <string>

#include "source/edit.h"

namespace shaderport {
namespace {

std::string Apply(const SourceFile& file, const FixIt& fix) {
  std::string text(file.Text());
  text.replace(fix.range.begin, fix.range.end - fix.range.begin, fix.replacement);
  return text;
}

TEST(StatementInsertion, FirstStatementTakesTheBodysIndentation) {
  const SourceFile file(0, "f", "void main() {\n\tfloat x = 1.0;\n}\n");
  const uint32_t brace_end = static_cast<uint32_t>(file.Text().find('{')) + 1;
  EXPECT_EQ(Apply(file, InsertFirstStatement(file, brace_end, "O = vec4(0.0);")),
            "void main() {\n\tO = vec4(0.0);\n\tfloat x = 1.0;\n}\n");
}

TEST(StatementInsertion, FirstStatementOfAnEmptyBodyIsOneLevelDeeper) {
  const SourceFile file(0, "f", "  void main()\n  {\n  }\n");
  const uint32_t brace_end = static_cast<uint32_t>(file.Text().find('{')) + 1;
  EXPECT_EQ(Apply(file, InsertFirstStatement(file, brace_end, "O = vec4(0.0);")),
            "  void main()\n  {\n      O = vec4(0.0);\n  }\n");
}

TEST(StatementInsertion, LastStatementGoesOnTheLineBeforeTheBrace) {
  const SourceFile file(0, "f", "vec3 f() {\r\n    if (true) return vec3(1.0);\r\n}\r\n");
  const uint32_t brace = static_cast<uint32_t>(file.Text().rfind('}'));
  EXPECT_EQ(Apply(file, InsertLastStatement(file, brace, "return vec3(0.0);")),
            "vec3 f() {\r\n    if (true) return vec3(1.0);\r\n    return vec3(0.0);\r\n}\r\n");
}

TEST(StatementInsertion, OneLineBlocksStayOnOneLine) {
  const SourceFile file(0, "f", "float f(int i) { if (i == 0) return 0.25; }\n");
  const uint32_t open = static_cast<uint32_t>(file.Text().find('{')) + 1;
  const uint32_t close = static_cast<uint32_t>(file.Text().rfind('}'));
  EXPECT_EQ(Apply(file, InsertLastStatement(file, close, "return 0.0;")),
            "float f(int i) { if (i == 0) return 0.25; return 0.0; }\n");
  EXPECT_EQ(Apply(file, InsertFirstStatement(file, open, "x = 0;")),
            "float f(int i) { x = 0; if (i == 0) return 0.25; }\n");
}

}  // namespace
}  // namespace shaderport
