// Statements of every kind, and the declaration/expression ambiguity.
#include <gtest/gtest.h>

#include "parse_helpers.h"

namespace shaderport::glsl::testing {
namespace {

// The statements of main's body.
std::vector<const Node*> Body(const Parsed& parsed) {
  std::vector<const Node*> out;
  const auto* fn = parsed.Root().declarations.back()->As<FunctionDeclaration>();
  if (fn == nullptr || fn->body == nullptr) return out;
  for (const Node* s : fn->body->statements) out.push_back(s);
  return out;
}

TEST(StatementTest, EveryStatementKind) {
  auto p = ParseText(
      "void main() {\n"
      "  { int a; }\n"
      "  ;\n"
      "  if (b) c(); else { d(); }\n"
      "  for (int i = 0; i < 3; ++i) continue;\n"
      "  while (x > 0.0) x -= 1.0;\n"
      "  do { break; } while (false);\n"
      "  switch (i) { case 0: f(); break; default: return; }\n"
      "  discard;\n"
      "  return;\n"
      "}\n");
  ASSERT_TRUE(p->result.diagnostics.empty()) << p->Messages()[0];
  std::vector<NodeKind> kinds;
  for (const Node* s : Body(*p)) kinds.push_back(s->kind);
  EXPECT_EQ(kinds, (std::vector<NodeKind>{NodeKind::kCompoundStatement, NodeKind::kEmptyStatement,
                                          NodeKind::kIfStatement, NodeKind::kForStatement,
                                          NodeKind::kWhileStatement, NodeKind::kDoWhileStatement,
                                          NodeKind::kSwitchStatement, NodeKind::kDiscardStatement,
                                          NodeKind::kReturnStatement}));
  const auto* if_st = Body(*p)[2]->As<IfStatement>();
  EXPECT_NE(if_st->else_branch, nullptr);
  const auto* for_st = Body(*p)[3]->As<ForStatement>();
  EXPECT_EQ(for_st->init->kind, NodeKind::kVariableDeclaration);
  EXPECT_TRUE(for_st->condition->IsExpr());
  EXPECT_EQ(for_st->body->kind, NodeKind::kContinueStatement);
  const auto* sw = Body(*p)[6]->As<SwitchStatement>();
  ASSERT_EQ(sw->body->statements.size(), 5u);
  EXPECT_EQ(sw->body->statements[0]->kind, NodeKind::kCaseLabel);
  EXPECT_EQ(sw->body->statements[3]->As<CaseLabel>()->value, nullptr);
}

TEST(StatementTest, EmptyForParts) {
  auto p = ParseText("void main() { for (;;) { break; } }\n");
  ASSERT_TRUE(p->result.diagnostics.empty());
  const auto* f = Body(*p)[0]->As<ForStatement>();
  EXPECT_EQ(f->init->kind, NodeKind::kEmptyStatement);
  EXPECT_EQ(f->condition, nullptr);
  EXPECT_EQ(f->increment, nullptr);
}

TEST(StatementTest, ConditionDeclaration) {
  auto p = ParseText("void main() { while (bool b = f()) {} }\n");
  ASSERT_TRUE(p->result.diagnostics.empty());
  EXPECT_EQ(Body(*p)[0]->As<WhileStatement>()->condition->kind, NodeKind::kVariableDeclaration);
}

TEST(StatementTest, MultiplicationIsAnExpressionWhenTheLeftIsNotAType) {
  auto p = ParseText("void main() { float a, b; a * b; vec3 c; c * a; }\n");
  ASSERT_TRUE(p->result.diagnostics.empty());
  auto body = Body(*p);
  EXPECT_EQ(body[1]->kind, NodeKind::kExpressionStatement);
  EXPECT_EQ(body[3]->kind, NodeKind::kExpressionStatement);
}

TEST(StatementTest, ConstructorStatementAndArrayDeclarationAreTold) {
  auto p = ParseText("void main() { vec3(1.0); float[2](1.0, 2.0); float[2] a; S s; }\n");
  ASSERT_TRUE(p->result.diagnostics.empty());
  auto body = Body(*p);
  EXPECT_EQ(body[0]->kind, NodeKind::kExpressionStatement);
  EXPECT_EQ(body[1]->kind, NodeKind::kExpressionStatement);
  EXPECT_EQ(body[2]->kind, NodeKind::kVariableDeclaration);
  EXPECT_EQ(body[3]->kind, NodeKind::kVariableDeclaration);
}

TEST(StatementTest, LocalStructAndPrecision) {
  auto p = ParseText("void main() { precision highp int; struct P { int a; } p; P q = P(1); }\n");
  ASSERT_TRUE(p->result.diagnostics.empty()) << p->Messages()[0];
  auto body = Body(*p);
  EXPECT_EQ(body[0]->kind, NodeKind::kPrecisionDeclaration);
  EXPECT_EQ(body[2]->As<VariableDeclaration>()->type->name_kind, TypeNameKind::kStruct);
}

TEST(StatementTest, GlobalSemicolonIsKeptWithoutError) {
  auto p = ParseText("void f() {};\n");
  EXPECT_TRUE(p->result.diagnostics.empty());
  ASSERT_EQ(p->Root().declarations.size(), 2u);
  EXPECT_EQ(p->Root().declarations[1]->kind, NodeKind::kEmptyStatement);
}

}  // namespace
}  // namespace shaderport::glsl::testing

namespace shaderport::glsl::testing {
namespace {

TEST(MultiFileTest, CommonAndPassKeepTheirOwnFiles) {
  auto p = ParseFiles({"#define SCALE 2.0\nstruct Ray { vec3 o; };\n",
                       "void mainImage(out vec4 c, in vec2 uv) { Ray r; c = vec4(SCALE); }\n"});
  ASSERT_TRUE(p->result.diagnostics.empty()) << p->Messages()[0];
  const auto& decls = p->Root().declarations;
  ASSERT_EQ(decls.size(), 2u);
  EXPECT_EQ(decls[0]->range.file, 0u);
  EXPECT_EQ(decls[1]->range.file, 1u);
  EXPECT_EQ(p->Root().range.file, 0u);
  // The struct declared in Common is a type in the pass.
  const auto* fn = decls[1]->As<FunctionDeclaration>();
  EXPECT_EQ(fn->body->statements[0]->kind, NodeKind::kVariableDeclaration);
  EXPECT_TRUE(CheckTreeShape(*p).empty());
}

}  // namespace
}  // namespace shaderport::glsl::testing
