// Round trip of the lexer over every shader we have.
#include <gtest/gtest.h>

#include "glsl/lex/lexer.h"
#include "test_corpora.h"

namespace shaderport::glsl {
namespace {

// Round trip plus structural checks; returns the number of lexer diagnostics.
constexpr size_t kConformanceStagesWithLexDiagnostics = 2;
constexpr size_t kShaderToyPassesWithLexDiagnostics = 0;

size_t CheckLex(const std::string& name, const std::string& text) {
  SourceFile file(0, name, text);
  LexedFile lexed = Lex(file);
  EXPECT_EQ(Reconstruct(file, lexed), text) << name;
  EXPECT_FALSE(lexed.tokens.empty());
  EXPECT_EQ(lexed.tokens.back().kind, TokenKind::kEndOfFile) << name;
  uint32_t previous_end = 0;
  for (const Token& t : lexed.tokens) {
    EXPECT_LE(previous_end, t.begin) << name;
    EXPECT_LE(t.end, text.size()) << name;
    previous_end = t.end;
  }
  return lexed.diagnostics.size();
}

TEST(LexerCorpus, ConformanceStagesRoundTrip) {
  const auto stages = testing::LoadConformanceStages();
  ASSERT_EQ(stages.size(), 2 * 2237u);
  size_t with_diagnostics = 0;
  for (const auto& s : stages) with_diagnostics += CheckLex(s.id, s.source) > 0;
  // Measured: non-ascii.vert (Japanese text) and shader-with-include.vert (`#include "x"`),
  // both expected to fail.
  EXPECT_EQ(with_diagnostics, kConformanceStagesWithLexDiagnostics);
}

TEST(LexerCorpus, ShaderToyPassesRoundTrip) {
  const auto passes = testing::LoadShaderToyPasses();
  ASSERT_EQ(passes.size(), 994u + 151u + 113u + 10u);
  size_t with_diagnostics = 0;
  for (const auto& p : passes) with_diagnostics += CheckLex(p.id, p.code) > 0;
  EXPECT_EQ(with_diagnostics, kShaderToyPassesWithLexDiagnostics);
}

TEST(LexerCorpus, RepoCorpusRoundTrip) {
  for (const auto& path : testing::CorpusFiles()) {
    CheckLex(path.string(), testing::ReadFile(path));
  }
}

}  // namespace
}  // namespace shaderport::glsl
