// The hand-written scanners that replaced std::regex in the text glslang compiles:
// each case is one the regex decided, plus lines ending in '\r' (CRLF files), which
// the regex's `.` refused, so those files were not repaired.
#include "rules/webgl/directive_text.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace shaderport::rules::directive_text {
namespace {

TEST(DirectiveText, DefinesAndTheirNames) {
  const auto object = ParseDefine("  #  define EPS.001");
  ASSERT_TRUE(object);
  EXPECT_EQ(object->name, "EPS");
  EXPECT_FALSE(object->function_like);
  EXPECT_EQ(std::string("  #  define EPS.001").substr(object->name_end), ".001");
  const auto function = ParseDefine("#define f(a, b,) a");
  ASSERT_TRUE(function);
  EXPECT_TRUE(function->function_like);
  EXPECT_FALSE(ParseDefine("#defineX 1"));
  EXPECT_FALSE(ParseDefine("#define 1X"));
  EXPECT_FALSE(ParseDefine("// #define X"));
}

TEST(DirectiveText, IfAndElifButNotIfdef) {
  EXPECT_TRUE(IsIfOrElif("#if N % 2u"));
  EXPECT_TRUE(IsIfOrElif("  # elif(1)"));
  EXPECT_TRUE(IsIfOrElif("#if N == 4u\r"));
  EXPECT_FALSE(IsIfOrElif("#ifdef N"));
  EXPECT_FALSE(IsIfOrElif("#ifndef N"));
  EXPECT_FALSE(IsIfOrElif("if (x) {}"));
}

TEST(DirectiveText, UnsignedDefines) {
  const auto plain = ParseUnsignedDefine("#define N 64u");
  ASSERT_TRUE(plain);
  EXPECT_EQ(plain->name, "N");
  EXPECT_EQ(plain->value, "64");
  const auto hex = ParseUnsignedDefine("#define MASK ( 0xFFu ) // low byte\r");
  ASSERT_TRUE(hex);
  EXPECT_EQ(hex->value, "0xFF");
  EXPECT_FALSE(ParseUnsignedDefine("#define N 64"));
  EXPECT_FALSE(ParseUnsignedDefine("#define N 64u + 1u"));
  EXPECT_FALSE(ParseUnsignedDefine("#define N(x) 64u"));
  EXPECT_FALSE(ParseUnsignedDefine("#define N 0xu"));
}

TEST(DirectiveText, UnsignedSuffixesGoOnlyFromNumbers) {
  EXPECT_EQ(WithoutUnsignedSuffixes("#if N % 2u == 0U && M > 0x1Fu"), "#if N % 2 == 0 && M > 0x1F");
  EXPECT_EQ(WithoutUnsignedSuffixes("#if a1u || 12uu || 1.5u"), "#if a1u || 12uu || 1.5");
}

TEST(DirectiveText, IdentifiersAndWords) {
  std::vector<std::string> words;
  ForEachIdentifier("a1 + 2b * _c(d)", [&](std::string_view w, size_t) { words.emplace_back(w); });
  EXPECT_EQ(words, (std::vector<std::string>{"a1", "_c", "d"}));
  EXPECT_TRUE(ContainsWord("normalize(x + 1e-6)", "normalize"));
  EXPECT_FALSE(ContainsWord("mynormalize(x)", "normalize"));
  EXPECT_FALSE(ContainsWord("normalize2(x)", "normalize"));
}

TEST(DirectiveText, EmptyCallsAndArguments) {
  EXPECT_TRUE(IsEmptyCall("F ( )"));
  EXPECT_FALSE(IsEmptyCall("F(x)"));
  EXPECT_TRUE(HasEmptyArgument("M(h, 2, )"));
  EXPECT_TRUE(HasEmptyArgument("M( ,a)"));
  EXPECT_TRUE(HasEmptyArgument("M(a,,b)"));
  EXPECT_FALSE(HasEmptyArgument("M(a, b)"));
}

TEST(DirectiveText, LinesSplitAtNewlinesOnly) {
  std::vector<std::pair<std::string, size_t>> lines;
  ForEachLine("a\r\nb\n", [&](std::string_view l, size_t at) { lines.emplace_back(l, at); });
  ASSERT_EQ(lines.size(), 3U);
  EXPECT_EQ(lines[0].first, "a\r");
  EXPECT_EQ(lines[1].second, 3U);
  EXPECT_EQ(lines[2].first, "");
}

}  // namespace
}  // namespace shaderport::rules::directive_text
