// Error reporting and recovery, reserved words, the nesting limit.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "base/limits.h"
#include "diag/rule_catalog.h"
#include "parse_helpers.h"

namespace shaderport::glsl::testing {
namespace {

std::vector<std::string> Rules(const Parsed& parsed) {
  std::vector<std::string> out;
  for (const auto& d : parsed.result.diagnostics) out.push_back(d.rule_id);
  return out;
}

std::string Where(const Parsed& parsed, size_t i) {
  const auto& d = parsed.result.diagnostics.at(i);
  LineColumn at = parsed.sources.Get(d.range.file).LocationOf(d.range.begin);
  return std::to_string(at.line) + ":" + std::to_string(at.column);
}

TEST(RecoveryTest, MissingSemicolonIsReportedAfterThePreviousToken) {
  auto p = ParseText("void main() {\n  float a = 1.0\n  a = 2.0;\n}\n");
  ASSERT_EQ(p->result.diagnostics.size(), 1u);
  EXPECT_EQ(p->result.diagnostics[0].message, "expected ';' after declaration");
  EXPECT_EQ(p->result.diagnostics[0].rule_id, "syntax/expected-token");
  EXPECT_EQ(Where(*p, 0), "2:16");
  // The next line was still parsed as a statement.
  const auto* fn = p->Root().declarations[0]->As<FunctionDeclaration>();
  EXPECT_EQ(fn->body->statements.size(), 2u);
}

TEST(RecoveryTest, SeveralErrorsInOneFileAreAllReported) {
  auto p = ParseText(
      "float a = ;\n"
      "void f() { x = (1.0 + ; y = 2.0; }\n"
      "vec3 b = vec3(1.0;\n"
      "int ok = 1;\n"
      "void g() { if x) {} z = 1; }\n");
  EXPECT_EQ(p->result.diagnostics.size(), 4u) << ::testing::PrintToString(p->Messages());
  EXPECT_EQ(Where(*p, 0), "1:11");
  EXPECT_EQ(Where(*p, 1), "2:23");
  EXPECT_EQ(Where(*p, 2), "3:18");
  EXPECT_EQ(Where(*p, 3), "5:15");
  // Declarations after the errors are still in the tree.
  ASSERT_EQ(p->Root().declarations.size(), 5u);
  EXPECT_EQ(p->Root().declarations[3]->As<VariableDeclaration>()->declarators[0]->name.text, "ok");
  EXPECT_TRUE(CheckTreeShape(*p).empty());
}

TEST(RecoveryTest, GarbageAtGlobalScope) {
  auto p = ParseText(") ] } 1 + 2; float a;\n@ float b;\n");
  EXPECT_FALSE(p->result.diagnostics.empty());
  int floats = 0;
  for (const Node* d : p->Root().declarations) {
    if (d->kind == NodeKind::kVariableDeclaration) ++floats;
  }
  EXPECT_EQ(floats, 2);
  EXPECT_TRUE(CheckTreeShape(*p).empty());
}

TEST(RecoveryTest, UnterminatedConstructsAtEndOfFile) {
  for (const char* text : {"void main() {", "void main() { f(", "struct S {", "float a[",
                           "uniform B {", "void f(int", "layout(", "void main() { if (",
                           "void main() { for (int i = 0;", "void main() { x = a ? b"}) {
    auto p = ParseText(text);
    EXPECT_TRUE(HasErrors(p->result.diagnostics)) << text;
    EXPECT_TRUE(CheckTreeShape(*p).empty()) << text;
  }
}

TEST(RecoveryTest, EveryRuleIdIsInTheCatalog) {
  auto p = ParseText("float a = ;\nvarying vec2 v;\nvoid f() { } }\n");
  for (const auto& d : p->result.diagnostics) {
    EXPECT_NE(FindRule(d.rule_id), nullptr) << d.rule_id;
  }
  EXPECT_NE(FindRule("syntax/nesting-too-deep"), nullptr);
}

TEST(ReservedWordTest, Es300ReservesVaryingButParsesOn) {
  auto p = ParseText("#version 300 es\nvarying vec2 uv;\nfloat sample;\n");
  EXPECT_EQ(Rules(*p), (std::vector<std::string>{"syntax/reserved-word", "syntax/reserved-word"}));
  EXPECT_EQ(p->result.diagnostics[0].message, "'varying' is a reserved word in GLSL ES 3.00");
  const auto* decl = p->Root().declarations[0]->As<VariableDeclaration>();
  ASSERT_NE(decl, nullptr);
  EXPECT_TRUE(decl->qualifiers.Has(QualifierKind::kVarying));
}

TEST(ReservedWordTest, Es300KeywordsArePlainNamesInEs100) {
  auto p = ParseText("float sample; float layout; float smooth; float uint;\n", 100);
  EXPECT_TRUE(p->result.diagnostics.empty()) << p->Messages()[0];
  auto q = ParseText("float switch;\n", 100);
  EXPECT_EQ(Rules(*q), std::vector<std::string>{"syntax/reserved-word"});
  auto r = ParseText("#version 300 es\nfloat layout;\n");
  EXPECT_EQ(Rules(*r), std::vector<std::string>{"syntax/expected-identifier"});
}

TEST(NestingTest, HundredThousandParenthesesGiveOneDiagnostic) {
  std::string text = "void main() { float x = ";
  text += std::string(100000, '(') + "1.0" + std::string(100000, ')') + "; float y; }\n";
  auto p = ParseText(text);
  EXPECT_EQ(Rules(*p), std::vector<std::string>{"syntax/nesting-too-deep"});
  const auto* fn = p->Root().declarations[0]->As<FunctionDeclaration>();
  EXPECT_EQ(fn->body->statements.size(), 2u);  // `float y;` after it was parsed
  EXPECT_TRUE(CheckTreeShape(*p).empty());
}

TEST(NestingTest, DeepBlocksUnaryAndIfChains) {
  const size_t n = 50000;
  std::vector<std::string> texts = {
      "void main() " + std::string(n, '{') + std::string(n, '}') + "\n",
      "void main() { x = " + std::string(n, '-') + "a; }\n",
      [&] {
        std::string t = "void main() { ";
        for (size_t i = 0; i < n; ++i) t += "if (a) ";
        return t + "b(); }\n";
      }(),
      "void main() { x = a" +
          [&] {
            std::string t;
            for (size_t i = 0; i < n; ++i) t += " = a";
            return t;
          }() +
          "; }\n",
      "void main() { f(" + std::string(n, '[') + "); }\n",
      "struct A { " +
          [&] {
            std::string t;
            for (size_t i = 0; i < n; ++i) t += "struct { ";
            return t;
          }() +
          "\n",
  };
  for (const auto& text : texts) {
    auto p = ParseText(text);
    int deep = 0;
    for (const auto& d : p->result.diagnostics) deep += d.rule_id == "syntax/nesting-too-deep";
    EXPECT_EQ(deep, 1) << text.substr(0, 40);
    EXPECT_TRUE(CheckTreeShape(*p).empty()) << text.substr(0, 40);
  }
}

// Where Chromium 156's parser gives up ("memory exhausted", a 10,000-entry stack): the
// largest counts it compiles, measured with these very texts around them.
TEST(NestingTest, StopsWhereBrowsersParsersStop) {
  const std::string globals = "precision highp float;\nout vec4 o;\nfloat f(float x){return x;}\n";
  const std::string body = "void main(){\n float y = 1.0;\n";
  const auto repeat = [](std::string_view s, size_t n) {
    std::string out;
    for (size_t i = 0; i < n; ++i) out += s;
    return out;
  };
  const auto parens = [&](size_t n) { return repeat("(", n) + "1.0" + repeat(")", n); };
  struct Case {
    const char* what;
    size_t largest;  // compiles in Chromium; one more does not
    std::function<std::string(size_t)> text;
  };
  const std::vector<Case> cases = {
      {"global initialiser", 9992,
       [&](size_t n) { return globals + "const float g = " + parens(n) + ";\n"; }},
      {"local initialiser", 9988,
       [&](size_t n) { return globals + body + "float x = " + parens(n) + ";\n}\n"; }},
      {"assignment", 9989,
       [&](size_t n) { return globals + body + "y = " + parens(n) + ";\n}\n"; }},
      {"first argument", 9987,
       [&](size_t n) { return globals + body + "float x = f(" + parens(n) + ");\n}\n"; }},
      {"negated parentheses", 4994,
       [&](size_t n) {
         return globals + body + "float x = " + repeat("-(", n) + "1.0" + repeat(")", n) + ";\n}\n";
       }},
      {"right operands", 3329,
       [&](size_t n) {
         return globals + body + "float x = " + repeat("2.0 * (", n) + "1.0" + repeat(")", n) +
                ";\n}\n";
       }},
      {"last operands of ?:", 1664,
       [&](size_t n) {
         return globals + body + "float x = " + repeat("true ? 1.0 : ", n) + "0.0;\n}\n";
       }},
      {"if statements", 1665,
       [&](size_t n) { return globals + body + repeat("if (true) ", n) + ";\n}\n"; }},
  };
  for (const Case& c : cases) {
    auto fits = ParseText(c.text(c.largest));
    EXPECT_TRUE(fits->result.diagnostics.empty()) << c.what;
    auto deeper = ParseText(c.text(c.largest + 1));
    EXPECT_EQ(Rules(*deeper), std::vector<std::string>{"syntax/nesting-too-deep"}) << c.what;
  }
}

TEST(LimitsTest, DiagnosticsAreCapped) {
  std::string text;
  for (int i = 0; i < 3000; ++i) text += "float = ;\n";
  auto p = ParseText(text);
  EXPECT_EQ(p->result.diagnostics.size(), limits::kMaxDiagnosticsPerFile + 1);
  EXPECT_EQ(p->result.diagnostics.back().rule_id, "syntax/too-many-errors");
  EXPECT_EQ(p->result.diagnostics.back().severity, Severity::kNote);
}

}  // namespace
}  // namespace shaderport::glsl::testing
