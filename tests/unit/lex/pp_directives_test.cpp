// One behaviour per test for each directive.
#include <gtest/gtest.h>

#include "diag/rule_catalog.h"
#include "pp_test_util.h"

namespace shaderport::glsl {
namespace {
using testing::ErrorCount;
using testing::Joined;
using testing::RuleIds;
using testing::RunPp;
using V = std::vector<std::string>;

TEST(PpDirectives, ObjectAndFunctionLikeMacros) {
  auto r = RunPp("#define A 1 + B\n#define B 2\n#define F(x, y) x * y\nA F(A, (3,4)) F\n");
  EXPECT_EQ(Joined(r.result), "1 + 2 1 + 2 * ( 3 , 4 ) F");
  EXPECT_TRUE(r.result.diagnostics.empty());
}

TEST(PpDirectives, MacroCallSpansLines) {
  auto r = RunPp("#define F(x) [x]\nF\n(\n1\n)\n");
  EXPECT_EQ(Joined(r.result), "[ 1 ]");
}

TEST(PpDirectives, EmptyArgumentForOneParameter) {
  auto r = RunPp("#define D(x) a x b\n#define Z() z\nD( ) D() Z()\n");
  EXPECT_EQ(Joined(r.result), "a b a b z");
  EXPECT_TRUE(r.result.diagnostics.empty());
}

TEST(PpDirectives, WrongArgumentCount) {
  auto r = RunPp("#define F(x, y) x\nF(1)\n");
  EXPECT_EQ(RuleIds(r.result), V{"preprocessor/macro-argument-count"});
  auto u = RunPp("#define F(x) x\nF(1\n");
  EXPECT_EQ(RuleIds(u.result), V{"preprocessor/unterminated-macro-call"});
  EXPECT_EQ(Joined(u.result), "F ( 1");
}

TEST(PpDirectives, SelfReferenceDoesNotRecurse) {
  auto r = RunPp("#define X X + 1\n#define F(a) F(a)\n#define P Q\n#define Q P\nX F(2) P\n");
  EXPECT_EQ(Joined(r.result), "X + 1 F ( 2 ) P");
  EXPECT_TRUE(r.result.diagnostics.empty());
}

TEST(PpDirectives, ArgumentsArePreExpanded) {
  auto r = RunPp("#define F(x) x\n#define G F(F(1))\nG F(G)\n");
  EXPECT_EQ(Joined(r.result), "1 1");
}

TEST(PpDirectives, TokenPasting) {
  auto r =
      RunPp("#define CAT(a, b) a ## b\n#define V vec\nCAT(V, 3) CAT(1, 2u) CAT(, x) CAT(<, <=)\n");
  EXPECT_EQ(Joined(r.result), "V3 12u x <<=");  // operands of ## are not expanded first
  const auto& t = r.result.tokens;
  EXPECT_EQ(t[0].kind, TokenKind::kIdentifier);
  EXPECT_EQ(t[1].kind, TokenKind::kUintLiteral);
  EXPECT_EQ(t[3].punct, Punct::kShiftLeftEqual);
  EXPECT_TRUE(t[0].in_macro_body);
  auto bad = RunPp("#define CAT(a, b) a ## b\nCAT(+, /)\n");
  EXPECT_EQ(RuleIds(bad.result), V{"preprocessor/invalid-token-paste"});
  EXPECT_EQ(Joined(bad.result), "+ /");
  auto edge = RunPp("#define E ## x\n");
  EXPECT_EQ(RuleIds(edge.result), V{"preprocessor/invalid-define"});
}

TEST(PpDirectives, PastedNameIsRescanned) {
  auto r = RunPp("#define CAT(a, b) a ## b\n#define AB 42\nCAT(A, B)\n");
  EXPECT_EQ(Joined(r.result), "42");
}

TEST(PpDirectives, Undef) {
  auto r = RunPp("#define A 1\n#undef A\nA\n#undef NEVER_DEFINED\n");
  EXPECT_EQ(Joined(r.result), "A");
  EXPECT_TRUE(r.result.diagnostics.empty());
}

TEST(PpDirectives, IfElifElse) {
  auto r = RunPp(
      "#if 1 + 2 * 3 == 7 && (8 >> 1) == 4 && -1 < 0 && ~0 == -1 && 7 % 4 == 3\na\n#endif\n"
      "#if 0\nb\n#elif 1 ? 0 : 1\nc\n#elif 0x10 == 020 && 16u == 16\nd\n#else\ne\n#endif\n"
      "#if !defined(A) && !defined A && defined GL_ES && GL_ES == 1\nf\n#endif\n");
  EXPECT_EQ(Joined(r.result), "a d f");
  EXPECT_TRUE(r.result.diagnostics.empty());
}

TEST(PpDirectives, IfdefIfndefNested) {
  auto r = RunPp(
      "#define A\n#ifdef A\n#ifndef A\nx\n#else\ny\n#endif\n#else\n#if 1\nz\n#endif\n#endif\n");
  EXPECT_EQ(Joined(r.result), "y");
}

TEST(PpDirectives, InactiveRegionsAreRecordedAndMayHoldAnything) {
  const std::string text = "#if 0\n$ @ ` #bogus\n#else\nok\n#endif\n";
  auto r = RunPp(text);
  EXPECT_EQ(Joined(r.result), "ok");
  EXPECT_TRUE(r.result.diagnostics.empty());
  ASSERT_EQ(r.result.inactive_regions.size(), 1u);
  const auto& region = r.result.inactive_regions[0];
  EXPECT_EQ(text.substr(region.begin, region.end - region.begin), "\n$ @ ` #bogus\n");
}

TEST(PpDirectives, SkippedElifIsNotEvaluated) {
  auto r = RunPp("#if 1\na\n#elif 1/0\nb\n#endif\n#if 0 && UNDEFINED\n#endif\n");
  EXPECT_EQ(Joined(r.result), "a");
  EXPECT_TRUE(r.result.diagnostics.empty());
}

TEST(PpDirectives, IfErrors) {
  EXPECT_EQ(RuleIds(RunPp("#if UNDEFINED\n#endif\n").result),
            V{"preprocessor/invalid-if-expression"});
  EXPECT_EQ(RuleIds(RunPp("#if 1 / 0\n#endif\n").result), V{"preprocessor/invalid-if-expression"});
  EXPECT_EQ(RuleIds(RunPp("#if\n#endif\n").result), V{"preprocessor/invalid-if-expression"});
  EXPECT_EQ(RuleIds(RunPp("#if 1.0\n#endif\n").result), V{"preprocessor/invalid-if-expression"});
  EXPECT_EQ(RuleIds(RunPp("#if defined(\n#endif\n").result), V{"preprocessor/invalid-defined"});
  EXPECT_EQ(RuleIds(RunPp("#if 1\n").result), V{"preprocessor/unterminated-conditional"});
  EXPECT_EQ(RuleIds(RunPp("#endif\n").result), V{"preprocessor/unmatched-conditional"});
  EXPECT_EQ(RuleIds(RunPp("#if 1\n#else\n#elif 1\n#endif\n").result),
            V{"preprocessor/unmatched-conditional"});
  EXPECT_EQ(RuleIds(RunPp("#ifdef\n#endif\n").result), V{"preprocessor/invalid-directive"});
}

TEST(PpDirectives, ConditionalMustEndInItsFile) {
  auto r = RunPp(V{"#if 1\n", "x\n#endif\n"});
  EXPECT_EQ(RuleIds(r.result),
            (V{"preprocessor/unterminated-conditional", "preprocessor/unmatched-conditional"}));
}

TEST(PpDirectives, MacrosCrossFiles) {
  auto r = RunPp(V{"#define COMMON 7\n", "COMMON\n"});
  EXPECT_EQ(Joined(r.result), "7");
  EXPECT_EQ(r.result.tokens[0].spelling.file, 0u);
  EXPECT_EQ(r.result.tokens[0].expansion.file, 1u);
}

TEST(PpDirectives, Version) {
  auto r = RunPp("// comment\n/* c */ #version 300 es\n");
  EXPECT_EQ(RuleIds(r.result), V{"preprocessor/version-not-first"});  // not on line 1
  auto ok = RunPp("#version 300 es\n__VERSION__\n");
  EXPECT_TRUE(ok.result.diagnostics.empty());
  EXPECT_TRUE(ok.result.version.present);
  EXPECT_EQ(ok.result.version.number, 300);
  EXPECT_EQ(ok.result.version.profile, "es");
  EXPECT_EQ(Joined(ok.result), "300");
  auto es1 = RunPp("\n// c\n#version 100\n__VERSION__\n");
  EXPECT_TRUE(es1.result.diagnostics.empty());
  EXPECT_EQ(Joined(es1.result), "100");
  EXPECT_EQ(RuleIds(RunPp("float x;\n#version 100\n").result), V{"preprocessor/version-not-first"});
  EXPECT_EQ(RuleIds(RunPp("#version 120\n").result), V{"preprocessor/unsupported-version"});
  EXPECT_EQ(RuleIds(RunPp("#version 300\n").result), V{"preprocessor/unsupported-version"});
  EXPECT_EQ(RuleIds(RunPp(V{"x\n", "#version 100\n"}).result), V{"preprocessor/version-not-first"});
  auto none = RunPp("x\n");
  EXPECT_FALSE(none.result.version.present);
  EXPECT_EQ(none.result.version.number, 100);
}

TEST(PpDirectives, Extension) {
  auto r = RunPp("#extension GL_OES_standard_derivatives : enable\n#extension all : warn\n");
  ASSERT_EQ(r.result.extensions.size(), 2u);
  EXPECT_EQ(r.result.extensions[0].name, "GL_OES_standard_derivatives");
  EXPECT_EQ(r.result.extensions[0].behavior, "enable");
  EXPECT_TRUE(r.result.diagnostics.empty());
  EXPECT_EQ(RuleIds(RunPp("#extension all : enable\n").result),
            V{"preprocessor/invalid-extension"});
  EXPECT_EQ(RuleIds(RunPp("#extension foo\n").result), V{"preprocessor/invalid-extension"});
  auto late1 = RunPp("float x;\n#extension GL_EXT_draw_buffers : require\n");
  ASSERT_EQ(late1.result.diagnostics.size(), 1u);
  EXPECT_EQ(late1.result.diagnostics[0].severity, Severity::kWarning);
  auto late3 = RunPp("#version 300 es\nfloat x;\n#extension GL_EXT_foo : require\n");
  EXPECT_EQ(ErrorCount(late3.result), 1u);
}

TEST(PpDirectives, PragmaIsRecordedErrorReports) {
  auto r = RunPp("#pragma STDGL invariant(all)\n#pragma optimize(off)\n");
  ASSERT_EQ(r.result.pragmas.size(), 2u);
  EXPECT_EQ(r.result.pragmas[0].text, "STDGL invariant ( all )");
  EXPECT_TRUE(r.result.diagnostics.empty());
  auto e = RunPp("#error this shader needs   WebGL 2\n");
  ASSERT_EQ(e.result.diagnostics.size(), 1u);
  EXPECT_EQ(e.result.diagnostics[0].rule_id, "preprocessor/error-directive");
  EXPECT_EQ(e.result.diagnostics[0].message, "#error this shader needs   WebGL 2");
}

TEST(PpDirectives, LineAndBuiltins) {
  auto r = RunPp("__LINE__ __FILE__\n#line 10 3\n__LINE__ __FILE__\n#define L __LINE__\nL\n");
  EXPECT_EQ(Joined(r.result), "1 0 10 3 12");
  EXPECT_EQ(RuleIds(RunPp("#line x\n").result), V{"preprocessor/invalid-line"});
}

// Parts of one composed text (ShaderToy: header, Common, pass): __LINE__ counts the
// lines before each part, and the whole is source string 0.
TEST(PpDirectives, LineCountsFromTheFirstLineOfEachPart) {
  auto r = RunPp({"__LINE__ __FILE__\n\n__LINE__\n", "__LINE__ __FILE__\n"}, {}, 0, {25, 28});
  EXPECT_EQ(Joined(r.result), "25 0 27 28 0");
  auto own = RunPp(std::vector<std::string>{"__LINE__\n", "__LINE__ __FILE__\n"});
  EXPECT_EQ(Joined(own.result), "1 1 1");
}

// Directives between a macro's arguments run as browsers run them; only the taken
// group's tokens become arguments. A call that never closes is still an error.
TEST(PpDirectives, DirectivesInsideMacroArguments) {
  auto r = RunPp("#define F(a, b) [a|b]\nF(\n#if 1\nx,\n#else\ny,\n#endif\n#define Z z\nZ)\n");
  EXPECT_EQ(Joined(r.result), "[ x | z ]");
  EXPECT_TRUE(r.result.diagnostics.empty());
  EXPECT_EQ(RuleIds(RunPp("#define F(a) a\nF(\n#if 1\nx\n#endif\n").result),
            V{"preprocessor/unterminated-macro-call"});
}

TEST(PpDirectives, UnknownDirectiveAndNullDirective) {
  EXPECT_EQ(
      RuleIds(RunPp("#include \"x.glsl\"\n").result),
      (V{"preprocessor/unknown-directive", "lex/invalid-character", "lex/invalid-character"}));
  EXPECT_TRUE(RunPp("#\n# /* c */\n").result.diagnostics.empty());
}

TEST(PpDirectives, ReservedAndRedefinedNames) {
  EXPECT_EQ(RuleIds(RunPp("#define GL_FOO 1\n").result), V{"preprocessor/reserved-macro-name"});
  EXPECT_EQ(RuleIds(RunPp("#define defined 1\n").result), V{"preprocessor/reserved-macro-name"});
  EXPECT_EQ(RuleIds(RunPp("#undef GL_ES\n").result), V{"preprocessor/predefined-macro"});
  EXPECT_EQ(RuleIds(RunPp("#define __LINE__ 1\n").result), V{"preprocessor/predefined-macro"});
  auto dunder = RunPp("#define MY__NAME 1\n");
  ASSERT_EQ(dunder.result.diagnostics.size(), 1u);
  EXPECT_EQ(dunder.result.diagnostics[0].severity, Severity::kWarning);
  EXPECT_TRUE(RunPp("#define A 1 +  2\n#define A 1 + 2\n").result.diagnostics.empty());
  auto redef = RunPp("#define A 1\n#define A 2\n");
  ASSERT_EQ(RuleIds(redef.result), V{"preprocessor/macro-redefined"});
  ASSERT_EQ(redef.result.diagnostics[0].notes.size(), 1u);
  EXPECT_EQ(redef.result.diagnostics[0].notes[0].range.begin, 8u);
  EXPECT_EQ(RuleIds(RunPp("#define F(a, a) a\n").result), V{"preprocessor/invalid-define"});
  EXPECT_EQ(RuleIds(RunPp("#define F(a b) a\n").result), V{"preprocessor/invalid-define"});
}

TEST(PpDirectives, PredefinedFromOptions) {
  auto r =
      RunPp("#if HW_PERFORMANCE == 1\nHW_PERFORMANCE FLAG\n#endif\n", {"HW_PERFORMANCE=1", "FLAG"});
  EXPECT_EQ(Joined(r.result), "1 1");
  EXPECT_TRUE(r.result.diagnostics.empty());
  // Predefined bodies have no file of their own: they point at the use.
  EXPECT_EQ(r.result.tokens[0].spelling, r.result.tokens[0].expansion);
  EXPECT_TRUE(r.result.tokens[0].in_macro_body);
}

TEST(PpDirectives, IdentifierLength) {
  const std::string name(257, 'x');
  EXPECT_EQ(RuleIds(RunPp(name + "\n").result), V{"preprocessor/identifier-too-long"});
  EXPECT_TRUE(RunPp("#version 300 es\n" + name + "\n").result.diagnostics.empty());
  EXPECT_TRUE(RunPp({name + "\n"}, {}, 1024).result.diagnostics.empty());
}

TEST(PpDirectives, EveryRuleIdIsInTheCatalog) {
  for (const char* text :
       {"#define GL_X\n", "#define F(x) x\nF(1,2)\n", "#if X\n", "#endif\n", "#foo\n",
        "#version 1\n", "#extension\n", "#line\n", "#error\n", "#define A 1\n#define A 2\n",
        "#define C(a,b) a##b\nC(+,-)\n", "#ifdef\n#endif\n", "#else x\n", "$\n", "/*"}) {
    for (const auto& d : RunPp(text).result.diagnostics) {
      EXPECT_NE(FindRule(d.rule_id), nullptr) << d.rule_id;
    }
  }
}

TEST(PpDirectives, AnUnterminatedTakenGroupSkipsNothing) {
  // Only a group that was skipping ends a skipped region at the end of the file.
  auto taken = RunPp("#if 1\nint a;\n");
  EXPECT_EQ(RuleIds(taken.result), V{"preprocessor/unterminated-conditional"});
  EXPECT_TRUE(taken.result.inactive_regions.empty());
  // A skipping group in the first file must not lend its start to the second file's.
  auto two = RunPp(std::vector<std::string>{"#ifdef\n", "#if 2"});
  for (const SourceRange& region : two.result.inactive_regions) {
    EXPECT_LE(region.begin, region.end);
    EXPECT_LE(region.end, two.sources->Get(region.file).Text().size());
  }
  auto skipped = RunPp("#if 0\nint a;\n");
  ASSERT_EQ(skipped.result.inactive_regions.size(), 1u);
  EXPECT_EQ(skipped.result.inactive_regions[0].begin, 5u);
  EXPECT_EQ(skipped.result.inactive_regions[0].end, 13u);
}
}  // namespace
}  // namespace shaderport::glsl
