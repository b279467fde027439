// Where expanded tokens come from, and the limits that keep hostile input bounded.
#include <gtest/gtest.h>

#include <chrono>

#include "base/limits.h"
#include "pp_test_util.h"

namespace shaderport::glsl {
namespace {
using testing::Joined;
using testing::RuleIds;
using testing::RunPp;
using V = std::vector<std::string>;

std::string_view Slice(const std::string& text, SourceRange r) {
  return std::string_view(text).substr(r.begin, r.end - r.begin);
}

TEST(PpExpansion, RangesAndMacroUseChain) {
  const std::string text =
      "#define INNER(v) (v + 1.0)\n#define OUTER(x) INNER(x) * 2.0\ny = OUTER(a);\n";
  auto r = RunPp(text);
  ASSERT_TRUE(r.result.diagnostics.empty());
  EXPECT_EQ(Joined(r.result), "y = ( a + 1.0 ) * 2.0 ;");
  const auto& t = r.result.tokens;
  // A plain token: spelling and expansion are itself.
  EXPECT_EQ(Slice(text, t[0].spelling), "y");
  EXPECT_EQ(t[0].expansion, t[0].spelling);
  EXPECT_EQ(t[0].macro_use, kNoMacroUse);
  EXPECT_FALSE(t[0].in_macro_body);
  // '(' is spelled in INNER's body; it stands for the whole OUTER(a).
  EXPECT_EQ(Slice(text, t[2].spelling), "(");
  EXPECT_LT(t[2].spelling.begin, 27u);  // inside the first #define line
  EXPECT_EQ(Slice(text, t[2].expansion), "OUTER(a)");
  EXPECT_TRUE(t[2].in_macro_body);
  // The argument keeps its spelling at the use: a fix there edits only this use.
  EXPECT_EQ(Slice(text, t[3].spelling), "a");
  EXPECT_EQ(t[3].spelling.begin, text.find("OUTER(a)") + 6);
  EXPECT_FALSE(t[3].in_macro_body);
  EXPECT_EQ(Slice(text, t[3].expansion), "OUTER(a)");
  // Chain: INNER's use (spelled in OUTER's body) has OUTER's use as parent.
  const auto& uses = r.result.macro_uses;
  const MacroUse& inner = uses[t[2].macro_use];
  EXPECT_EQ(inner.name, "INNER");
  EXPECT_EQ(Slice(text, inner.definition), "INNER");
  ASSERT_NE(inner.parent, kNoMacroUse);
  const MacroUse& outer = uses[inner.parent];
  EXPECT_EQ(outer.name, "OUTER");
  EXPECT_EQ(Slice(text, outer.use), "OUTER(a)");
  EXPECT_EQ(outer.parent, kNoMacroUse);
  EXPECT_EQ(Slice(text, inner.use), "INNER(x)");
  // Tokens of OUTER's own body point at OUTER's use.
  EXPECT_EQ(uses[t[7].macro_use].name, "OUTER");
  EXPECT_EQ(Slice(text, t[7].spelling), "*");
}

TEST(PpExpansion, LeadingSpaceAndLineStartFollowTheUse) {
  auto r = RunPp("#define A   x y\nfoo\nA\n");
  ASSERT_EQ(r.result.tokens.size(), 4u);
  EXPECT_TRUE(r.result.tokens[1].at_line_start);
  EXPECT_TRUE(r.result.tokens[2].leading_space);
}

TEST(PpExpansion, ContinuationsInsideTokensAreRemovedFromText) {
  const std::string text = "flo\\\nat x = 1.\\\n5;\n";
  auto r = RunPp(text);
  EXPECT_EQ(Joined(r.result), "float x = 1.5 ;");
  EXPECT_EQ(Slice(text, r.result.tokens[0].spelling), "flo\\\nat");
}

TEST(PpExpansion, ExponentialMacroStopsQuickly) {
  std::string text;
  for (int i = 0; i < 40; ++i) {
    text += "#define M" + std::to_string(i) + " M" + std::to_string(i + 1) + " M" +
            std::to_string(i + 1) + "\n";
  }
  text += "M0\n";
  const auto start = std::chrono::steady_clock::now();
  auto r = RunPp(text);
  const auto seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(RuleIds(r.result), V{"preprocessor/expansion-too-large"});
  EXPECT_LE(r.result.tokens.size(), limits::kMaxExpandedTokens);
  EXPECT_LE(r.result.macro_uses.size(), limits::kMaxExpandedTokens);
  EXPECT_LT(seconds, 20.0);
}

TEST(PpExpansion, ARescanTakesItsArgumentsFromTheTextThatFollows) {
  // The expander reads the file's tokens as it goes: an expansion that ends in a
  // function-like macro's name takes the '(' and arguments that come after the use.
  auto r = RunPp("#define F G\n#define G(x) [x]\nint a; F(1) F\n(2) F\n");
  EXPECT_EQ(Joined(r.result), "int a ; [ 1 ] [ 2 ] G");
  EXPECT_TRUE(r.result.diagnostics.empty());
}

TEST(PpExpansion, DeepMacroChainIsCut) {
  std::string text;
  for (int i = 0; i < 1000; ++i) {
    text += "#define C" + std::to_string(i) + " C" + std::to_string(i + 1) + "\n";
  }
  text += "C0\n";
  auto r = RunPp(text);
  EXPECT_EQ(RuleIds(r.result), V{"preprocessor/macro-too-deep"});
  ASSERT_EQ(r.result.tokens.size(), 2u);
  EXPECT_EQ(r.result.tokens[0].text, "C" + std::to_string(limits::kMaxMacroDepth));
}

TEST(PpExpansion, DeeplyNestedCallsAreBounded) {
  std::string text = "#define F(x) x\n";
  for (int i = 0; i < 20000; ++i) text += "F(";
  text += "1";
  for (int i = 0; i < 20000; ++i) text += ")";
  auto r = RunPp(text + "\n");
  // Either limit may stop it first; what matters is that it stops, in bounded memory.
  ASSERT_FALSE(r.result.diagnostics.empty());
  EXPECT_EQ(r.result.diagnostics[0].severity, Severity::kError);
}

TEST(PpExpansion, HundredThousandNestedIfs) {
  std::string text;
  for (int i = 0; i < 100000; ++i) text += "#if 1\n";
  text += "x\n";
  for (int i = 0; i < 100000; ++i) text += "#endif\n";
  text += "y\n";
  auto r = RunPp(text);
  EXPECT_EQ(RuleIds(r.result), V{"preprocessor/conditional-too-deep"});
  EXPECT_EQ(Joined(r.result), "y");  // groups past the limit are skipped, and matched
}

TEST(PpExpansion, DeepIfExpressionIsBounded) {
  std::string text = "#if ";
  for (int i = 0; i < 100000; ++i) text += "(-";
  text += "1";
  for (int i = 0; i < 100000; ++i) text += ")";
  auto r = RunPp(text + "\n#endif\n");
  // The browsers' limit (docs/limits.md, "Nesting"), reported as the parser's breach.
  EXPECT_EQ(RuleIds(r.result), V{"syntax/nesting-too-deep"});
}

// Under the expansion limit, over what glslang is given: one macro used 2,100 times
// (4,001,000 tokens took every command past 2 GiB inside glslang).
TEST(PpExpansion, OutputOverTheCompiledLimitIsOneErrorAtTheFirstTokenPast) {
  std::string body;
  for (int i = 0; i < 250; ++i) body += " a +";
  std::string text = "#define A" + body + "\nfloat x = ";
  const size_t first_use = text.size();
  for (int i = 0; i < 2100; ++i) text += "A ";
  auto r = RunPp(text + "1.0;\n");
  EXPECT_EQ(RuleIds(r.result), V{"preprocessor/output-too-large"});
  ASSERT_GT(r.result.tokens.size(), limits::kMaxCompiledTokens);
  EXPECT_GT(r.result.diagnostics.front().range.begin, first_use);
  // Just under it: nothing to say.
  auto fits = RunPp("#define A" + body + "\nfloat x = A A 1.0;\n");
  EXPECT_TRUE(fits.result.diagnostics.empty());
}

}  // namespace
}  // namespace shaderport::glsl
