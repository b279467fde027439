// Expressions: precedence, associativity, calls vs constructors, postfix chains.
#include <gtest/gtest.h>

#include "parse_helpers.h"

namespace shaderport::glsl::testing {
namespace {

// The initializer of `float x = <expr>;` inside main.
struct ExprFixture {
  std::unique_ptr<Parsed> parsed;
  const Expr* expr = nullptr;
};

ExprFixture ParseExpr(const std::string& expr, const std::string& prelude = "") {
  ExprFixture f;
  f.parsed = ParseText(prelude + "void main() { x = " + expr + "; }\n");
  const auto* fn = f.parsed->Root().declarations.back()->As<FunctionDeclaration>();
  if (fn == nullptr || fn->body == nullptr || fn->body->statements.empty()) return f;
  const auto* st = fn->body->statements[0]->As<ExpressionStatement>();
  if (st == nullptr) return f;
  f.expr = st->expression->As<AssignmentExpr>()->rhs;
  return f;
}

// A compact S-expression of an expression tree, to check shapes.
std::string Shape(const Node* node) {
  if (node == nullptr) return "null";
  switch (node->kind) {
    case NodeKind::kIdentifierExpr:
      return node->As<IdentifierExpr>()->name;
    case NodeKind::kLiteralExpr:
      return node->As<LiteralExpr>()->text;
    case NodeKind::kParenExpr:
      return "(" + Shape(node->As<ParenExpr>()->inner) + ")";
    case NodeKind::kBinaryExpr: {
      const auto* b = node->As<BinaryExpr>();
      return "[" + Shape(b->lhs) + BinaryOpSpelling(b->op) + Shape(b->rhs) + "]";
    }
    case NodeKind::kAssignmentExpr: {
      const auto* b = node->As<AssignmentExpr>();
      return "[" + Shape(b->lhs) + AssignOpSpelling(b->op) + Shape(b->rhs) + "]";
    }
    case NodeKind::kUnaryExpr: {
      const auto* u = node->As<UnaryExpr>();
      bool post = u->op == UnaryOp::kPostIncrement || u->op == UnaryOp::kPostDecrement;
      return post ? "[" + Shape(u->operand) + UnaryOpSpelling(u->op) + "]"
                  : "[" + std::string(UnaryOpSpelling(u->op)) + Shape(u->operand) + "]";
    }
    case NodeKind::kConditionalExpr: {
      const auto* c = node->As<ConditionalExpr>();
      return "[" + Shape(c->condition) + "?" + Shape(c->if_true) + ":" + Shape(c->if_false) + "]";
    }
    case NodeKind::kCallExpr: {
      const auto* c = node->As<CallExpr>();
      std::string out = c->call_kind == CallKind::kConstructor ? "ctor:" : "call:";
      if (c->object != nullptr) out = Shape(c->object) + ".";
      out += c->callee.text;
      if (c->constructor_type != nullptr && !c->constructor_type->array.empty()) out += "[]";
      out += "(";
      for (size_t i = 0; i < c->arguments.size(); ++i) {
        out += (i ? "," : "") + Shape(c->arguments[i]);
      }
      return out + ")";
    }
    case NodeKind::kMemberExpr:
      return Shape(node->As<MemberExpr>()->object) + "." + node->As<MemberExpr>()->member.text;
    case NodeKind::kIndexExpr:
      return Shape(node->As<IndexExpr>()->base) + "[" + Shape(node->As<IndexExpr>()->index) + "]";
    case NodeKind::kErrorExpr:
      return "<error>";
    default:
      return "?";
  }
}

std::string ShapeOf(const std::string& expr, const std::string& prelude = "") {
  ExprFixture f = ParseExpr(expr, prelude);
  if (!f.parsed->result.diagnostics.empty()) return "diag: " + f.parsed->Messages()[0];
  return Shape(f.expr);
}

TEST(ExpressionTest, BinaryPrecedenceAndAssociativity) {
  EXPECT_EQ(ShapeOf("a + b * c"), "[a+[b*c]]");
  EXPECT_EQ(ShapeOf("a - b - c"), "[[a-b]-c]");
  EXPECT_EQ(ShapeOf("a || b && c ^^ d"), "[a||[[b&&c]^^d]]");
  EXPECT_EQ(ShapeOf("a | b ^ c & d"), "[a|[b^[c&d]]]");
  EXPECT_EQ(ShapeOf("a == b < c"), "[a==[b<c]]");
  EXPECT_EQ(ShapeOf("a << 1 + b"), "[a<<[1+b]]");
  EXPECT_EQ(ShapeOf("a % b / c"), "[[a%b]/c]");
}

TEST(ExpressionTest, AssignmentTernaryAndComma) {
  EXPECT_EQ(ShapeOf("a = b += c"), "[a=[b+=c]]");
  EXPECT_EQ(ShapeOf("a ? b : c ? d : e"), "[a?b:[c?d:e]]");
  EXPECT_EQ(ShapeOf("(a, b, c)"), "([[a,b],c])");
  EXPECT_EQ(ShapeOf("a ? b = 1.0 : c"), "[a?[b=1.0]:c]");
  EXPECT_EQ(ShapeOf("a <<= 2"), "[a<<=2]");
}

TEST(ExpressionTest, UnaryPrefixAndPostfix) {
  EXPECT_EQ(ShapeOf("-a++"), "[-[a++]]");
  EXPECT_EQ(ShapeOf("!!b"), "[![!b]]");
  EXPECT_EQ(ShapeOf("--a[0].x"), "[--a[0].x]");
  EXPECT_EQ(ShapeOf("~i * -j"), "[[~i]*[-j]]");
}

TEST(ExpressionTest, CallsConstructorsAndMethods) {
  EXPECT_EQ(ShapeOf("vec3(1.0)"), "ctor:vec3(1.0)");
  EXPECT_EQ(ShapeOf("f(a, g(b))"), "call:f(a,call:g(b))");
  EXPECT_EQ(ShapeOf("float[3](1.0, 2.0, 3.0)"), "ctor:float[](1.0,2.0,3.0)");
  EXPECT_EQ(ShapeOf("a.length()"), "a.length()");
  EXPECT_EQ(ShapeOf("S(1.0).a", "struct S { float a; };\n"), "ctor:S(1.0).a");
  EXPECT_EQ(ShapeOf("texture(s, uv).rgb[1]"), "call:texture(s,uv).rgb[1]");
  ExprFixture f = ParseExpr("f(void)");
  EXPECT_TRUE(f.expr->As<CallExpr>()->void_argument);
}

TEST(ExpressionTest, Literals) {
  ExprFixture f = ParseExpr("0x1Fu + 017 + 1.5e1 + 2.0f + 4294967296");
  ASSERT_TRUE(f.parsed->result.diagnostics.empty());
  std::vector<const LiteralExpr*> literals;
  VisitPreorder(*f.expr, [&](const Node& n, uint32_t) {
    if (const auto* l = n.As<LiteralExpr>()) literals.push_back(l);
    return true;
  });
  ASSERT_EQ(literals.size(), 5u);
  EXPECT_EQ(literals[0]->literal_kind, LiteralKind::kUint);
  EXPECT_EQ(literals[0]->int_value, 31u);
  EXPECT_EQ(literals[1]->int_value, 15u);
  EXPECT_DOUBLE_EQ(literals[2]->float_value, 15.0);
  EXPECT_DOUBLE_EQ(literals[3]->float_value, 2.0);
  EXPECT_TRUE(literals[4]->int_overflow);
  EXPECT_FALSE(literals[0]->int_overflow);
}

TEST(ExpressionTest, LongChainsAreIterativeAndWalkable) {
  std::string expr = "a";
  for (int i = 0; i < 20000; ++i) expr += " + a";
  ExprFixture f = ParseExpr(expr);
  EXPECT_TRUE(f.parsed->result.diagnostics.empty());
  uint32_t max_depth = 0, count = 0;
  VisitPreorder(f.parsed->result.tree, [&](const Node&, uint32_t depth) {
    max_depth = std::max(max_depth, depth);
    return true;
  });
  VisitPostorder(f.parsed->result.tree, [&](const Node&) { ++count; });
  EXPECT_GT(max_depth, 20000u);
  EXPECT_EQ(count, f.parsed->result.tree.NodeCount());
}

TEST(ExpressionTest, RangesCoverTheWrittenText) {
  ExprFixture f = ParseExpr("foo(1.0, b) * 2.0");
  const auto& text = f.parsed->sources.Get(0).Text();
  auto slice = [&](const Node* n) {
    return std::string(text.substr(n->range.begin, n->range.Size()));
  };
  EXPECT_EQ(slice(f.expr), "foo(1.0, b) * 2.0");
  EXPECT_EQ(slice(f.expr->As<BinaryExpr>()->lhs), "foo(1.0, b)");
  EXPECT_EQ(slice(f.expr->As<BinaryExpr>()->lhs->As<CallExpr>()->arguments[1]), "b");
}

TEST(ExpressionTest, MacroExpansionsUseTheMacroUseRange) {
  auto p = ParseText("#define TWO (1.0 + 1.0)\nvoid main() { x = TWO * y; }\n");
  ASSERT_TRUE(p->result.diagnostics.empty());
  const auto& text = p->sources.Get(0).Text();
  bool found = false;
  VisitPreorder(p->result.tree, [&](const Node& n, uint32_t) {
    if (n.kind == NodeKind::kParenExpr) {
      EXPECT_EQ(text.substr(n.range.begin, n.range.Size()), "TWO");
      found = true;
    }
    return true;
  });
  EXPECT_TRUE(found);
  EXPECT_TRUE(CheckTreeShape(*p).empty());
}

}  // namespace
}  // namespace shaderport::glsl::testing
