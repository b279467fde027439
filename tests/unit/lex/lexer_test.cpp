#include "glsl/lex/lexer.h"

#include <gtest/gtest.h>

#include <string>

#include "base/limits.h"
#include "diag/rule_catalog.h"

namespace shaderport::glsl {
namespace {

struct Lexed {
  SourceFile file;
  LexedFile lexed;
};

Lexed LexText(std::string text) {
  Lexed out{SourceFile(0, "t.glsl", std::move(text)), {}};
  out.lexed = Lex(out.file);
  return out;
}

// "kind:text" of every token but the final end of file.
std::vector<std::string> Kinds(const LexedFile& lexed) {
  std::vector<std::string> out;
  for (const Token& t : lexed.tokens) {
    if (t.kind == TokenKind::kEndOfFile) continue;
    out.push_back(std::string(TokenKindName(t.kind)) + ":" + std::string(t.text));
  }
  return out;
}

using V = std::vector<std::string>;

TEST(Lexer, EmptyFileHasOnlyEndOfFile) {
  auto l = LexText("");
  ASSERT_EQ(l.lexed.tokens.size(), 1u);
  EXPECT_EQ(l.lexed.tokens[0].kind, TokenKind::kEndOfFile);
  EXPECT_TRUE(l.lexed.diagnostics.empty());
}

TEST(Lexer, Numbers) {
  auto l = LexText("1 017 0x1F 0X1fu 3u 1. .5 1e3 1.0e-3 1.0f 2E+4F 1.5e 0x");
  EXPECT_EQ(Kinds(l.lexed), (V{"int:1", "int:017", "int:0x1F", "uint:0X1fu", "uint:3u", "float:1.",
                               "float:.5", "float:1e3", "float:1.0e-3", "float:1.0f", "float:2E+4F",
                               "float:1.5", "identifier:e", "int:0x"}));
}

TEST(Lexer, IdentifiersAndPunctuators) {
  auto l = LexText("a_1 _b<<=c>>=d^^e##f.g->h");
  EXPECT_EQ(Kinds(l.lexed), (V{"identifier:a_1", "identifier:_b", "punctuator:<<=", "identifier:c",
                               "punctuator:>>=", "identifier:d", "punctuator:^^", "identifier:e",
                               "punctuator:##", "identifier:f", "punctuator:.", "identifier:g",
                               "punctuator:-", "punctuator:>", "identifier:h"}));
  EXPECT_EQ(l.lexed.tokens[2].punct, Punct::kShiftLeftEqual);
  EXPECT_EQ(l.lexed.tokens[8].punct, Punct::kHashHash);
}

TEST(Lexer, HashAtLineStartIsDirective) {
  auto l = LexText("  # define X #\n#if\na #b");
  const auto& t = l.lexed.tokens;
  EXPECT_EQ(t[0].kind, TokenKind::kHash);
  EXPECT_TRUE(t[0].at_line_start);
  EXPECT_TRUE(t[0].leading_space);
  EXPECT_EQ(t[3].punct, Punct::kHashInLine);
  EXPECT_EQ(t[4].kind, TokenKind::kHash);
  EXPECT_EQ(t[7].punct, Punct::kHashInLine);
  EXPECT_FALSE(t[7].at_line_start);
}

TEST(Lexer, LineContinuationBetweenAndInsideTokens) {
  auto l = LexText("a \\\nb flo\\\r\nat x\\\n");
  EXPECT_EQ(Kinds(l.lexed),
            (V{"identifier:a", "identifier:b", "identifier:flo\\\r\nat", "identifier:x"}));
  EXPECT_FALSE(l.lexed.tokens[1].at_line_start);  // a continuation does not end the line
  EXPECT_EQ(RemoveLineContinuations(l.lexed.tokens[2].text), "float");
  // The trailing continuation is trivia of the end-of-file token.
  const Token& eof = l.lexed.tokens.back();
  ASSERT_EQ(eof.trivia_end - eof.trivia_begin, 1u);
  EXPECT_EQ(l.lexed.trivia[eof.trivia_begin].kind, TriviaKind::kLineContinuation);
  EXPECT_EQ(Reconstruct(l.file, l.lexed), l.file.Text());
}

TEST(Lexer, Comments) {
  auto l = LexText("a // c \\\n still comment\nb /* x\n y */ c");
  EXPECT_EQ(Kinds(l.lexed), (V{"identifier:a", "identifier:b", "identifier:c"}));
  EXPECT_TRUE(l.lexed.tokens[1].at_line_start);
  EXPECT_TRUE(l.lexed.tokens[2].leading_space);
  EXPECT_FALSE(l.lexed.tokens[2].at_line_start);  // a comment counts as a space, as in C
  EXPECT_TRUE(l.lexed.diagnostics.empty());
}

TEST(Lexer, UnterminatedCommentRunsToEnd) {
  auto l = LexText("a /* b\n c");
  EXPECT_EQ(Kinds(l.lexed), (V{"identifier:a"}));
  ASSERT_EQ(l.lexed.diagnostics.size(), 1u);
  EXPECT_EQ(l.lexed.diagnostics[0].rule_id, "lex/unterminated-comment");
  EXPECT_EQ(l.lexed.diagnostics[0].range.begin, 2u);
  EXPECT_EQ(Reconstruct(l.file, l.lexed), l.file.Text());
}

TEST(Lexer, InvalidBytesAreTokensWithOneDiagnosticPerRun) {
  std::string text = "a $@ b ";
  text += '\0';
  text += "\xFF\xFE c \xC2\xA0 d \\ e";
  auto l = LexText(text);
  EXPECT_EQ(Reconstruct(l.file, l.lexed), text);
  size_t invalid = 0;
  for (const Token& t : l.lexed.tokens) invalid += t.kind == TokenKind::kInvalid;
  EXPECT_EQ(invalid, 7u);  // $ @ NUL FF FE U+00A0 backslash
  ASSERT_EQ(l.lexed.diagnostics.size(), 4u);
  for (const auto& d : l.lexed.diagnostics) EXPECT_EQ(d.rule_id, "lex/invalid-character");
  EXPECT_EQ(l.lexed.diagnostics[0].range.begin, 2u);
  EXPECT_EQ(l.lexed.diagnostics[0].range.end, 4u);
  EXPECT_NE(l.lexed.diagnostics[2].message.find("U+00A0"), std::string::npos);
}

TEST(Lexer, CrOnlyNewlines) {
  auto l = LexText("#define A\r#if A\rx\r#endif\r");
  EXPECT_EQ(Reconstruct(l.file, l.lexed), l.file.Text());
  int hashes = 0;
  for (const Token& t : l.lexed.tokens) hashes += t.kind == TokenKind::kHash;
  EXPECT_EQ(hashes, 3);
  EXPECT_EQ(l.file.LocationOf(l.lexed.tokens[6].begin).line, 3u);  // x
}

TEST(Lexer, TokenLimitKeepsRoundTrip) {
  std::string text(limits::kMaxTokens + 10, ';');
  auto l = LexText(text);
  EXPECT_EQ(l.lexed.tokens.size(), limits::kMaxTokens + 1);
  ASSERT_EQ(l.lexed.diagnostics.size(), 1u);
  EXPECT_EQ(l.lexed.diagnostics[0].rule_id, "lex/too-many-tokens");
  EXPECT_EQ(Reconstruct(l.file, l.lexed), text);
}

TEST(Lexer, DiagnosticIdsAreInCatalog) {
  for (const char* id :
       {"lex/invalid-character", "lex/unterminated-comment", "lex/too-many-tokens"}) {
    EXPECT_NE(FindRule(id), nullptr) << id;
  }
}

TEST(Lexer, DumpTokens) {
  auto l = LexText("a\n 1.5 '\n");
  EXPECT_EQ(DumpTokens(l.file, l.lexed),
            "1:1 identifier 'a'\n2:2 float '1.5'\n2:6 invalid '\\''\n3:1 eof ''\n");
}

}  // namespace
}  // namespace shaderport::glsl
