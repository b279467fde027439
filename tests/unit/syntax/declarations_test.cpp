// Declarations: variables, arrays, structs, functions, blocks, qualifiers, precision.
#include <gtest/gtest.h>

#include "parse_helpers.h"

namespace shaderport::glsl::testing {
namespace {

template <class T>
const T* Decl(const Parsed& parsed, size_t index) {
  const auto& decls = parsed.Root().declarations;
  if (index >= decls.size()) return nullptr;
  return decls[index]->As<T>();
}

TEST(DeclarationTest, MultipleDeclaratorsWithInitializersAndArrays) {
  auto p = ParseText("const highp float a = 1.0, b[3], c;\n");
  ASSERT_TRUE(p->result.diagnostics.empty()) << p->Messages()[0];
  const auto* decl = Decl<VariableDeclaration>(*p, 0);
  ASSERT_NE(decl, nullptr);
  EXPECT_TRUE(decl->qualifiers.Has(QualifierKind::kConst));
  EXPECT_EQ(decl->type->name.text, "float");
  EXPECT_EQ(decl->type->precision, Precision::kHigh);
  ASSERT_EQ(decl->declarators.size(), 3u);
  EXPECT_EQ(decl->declarators[0]->name.text, "a");
  EXPECT_NE(decl->declarators[0]->initializer, nullptr);
  EXPECT_EQ(decl->declarators[1]->array.size(), 1u);
  EXPECT_EQ(decl->declarators[2]->initializer, nullptr);
}

TEST(DeclarationTest, ArrayOnTypeAndUnsizedArray) {
  auto p = ParseText("float[3] a; float b[]; float[2] c[4];\n");
  ASSERT_TRUE(p->result.diagnostics.empty());
  EXPECT_EQ(Decl<VariableDeclaration>(*p, 0)->type->array.size(), 1u);
  EXPECT_EQ(Decl<VariableDeclaration>(*p, 1)->declarators[0]->array[0].size, nullptr);
  EXPECT_EQ(Decl<VariableDeclaration>(*p, 2)->declarators[0]->array.size(), 1u);
}

TEST(DeclarationTest, StructsNestedAndWithInstance) {
  auto p = ParseText(
      "struct Inner { vec2 p; };\n"
      "struct Outer { Inner i; lowp float f[2]; } o, o2;\n"
      "Outer make() { Outer x; return x; }\n");
  ASSERT_TRUE(p->result.diagnostics.empty()) << p->Messages()[0];
  const auto* inner = Decl<VariableDeclaration>(*p, 0);
  ASSERT_NE(inner->type->struct_def, nullptr);
  EXPECT_EQ(inner->type->struct_def->name.text, "Inner");
  EXPECT_TRUE(inner->declarators.empty());
  const auto* outer = Decl<VariableDeclaration>(*p, 1);
  ASSERT_EQ(outer->type->struct_def->fields.size(), 2u);
  EXPECT_EQ(outer->type->struct_def->fields[0]->type->name_kind, TypeNameKind::kStruct);
  EXPECT_EQ(outer->declarators.size(), 2u);
  const auto* fn = Decl<FunctionDeclaration>(*p, 2);
  ASSERT_NE(fn, nullptr);
  EXPECT_EQ(fn->return_type->name_kind, TypeNameKind::kStruct);
  EXPECT_EQ(fn->body->statements[0]->kind, NodeKind::kVariableDeclaration);
}

TEST(DeclarationTest, AnonymousStructInstance) {
  auto p = ParseText("struct { float a; } s;\n");
  ASSERT_TRUE(p->result.diagnostics.empty());
  const auto* decl = Decl<VariableDeclaration>(*p, 0);
  EXPECT_TRUE(decl->type->struct_def->name.Empty());
  EXPECT_EQ(decl->declarators[0]->name.text, "s");
}

TEST(DeclarationTest, FunctionsPrototypesAndParameters) {
  auto p = ParseText(
      "float f(void);\n"
      "void g(in highp vec2 p, out float r[2], inout int, const float k) {}\n"
      "float f(void) { return 1.0; }\n");
  ASSERT_TRUE(p->result.diagnostics.empty()) << p->Messages()[0];
  const auto* proto = Decl<FunctionDeclaration>(*p, 0);
  EXPECT_TRUE(proto->void_parameter);
  EXPECT_EQ(proto->body, nullptr);
  const auto* g = Decl<FunctionDeclaration>(*p, 1);
  ASSERT_EQ(g->parameters.size(), 4u);
  EXPECT_TRUE(g->parameters[0]->qualifiers.Has(QualifierKind::kIn));
  EXPECT_EQ(g->parameters[0]->type->precision, Precision::kHigh);
  EXPECT_EQ(g->parameters[1]->array.size(), 1u);
  EXPECT_TRUE(g->parameters[2]->name.Empty());
  EXPECT_NE(Decl<FunctionDeclaration>(*p, 2)->body, nullptr);
}

TEST(DeclarationTest, PrecisionAndQualifierOnlyDeclarations) {
  auto p = ParseText(
      "#version 300 es\nprecision mediump float;\ninvariant gl_Position;\n"
      "layout(std140) uniform;\n");
  ASSERT_TRUE(p->result.diagnostics.empty()) << p->Messages()[0];
  const auto* precision = Decl<PrecisionDeclaration>(*p, 0);
  ASSERT_NE(precision, nullptr);
  EXPECT_EQ(precision->precision, Precision::kMedium);
  EXPECT_EQ(precision->type->name.text, "float");
  const auto* invariant = Decl<QualifierDeclaration>(*p, 1);
  ASSERT_NE(invariant, nullptr);
  ASSERT_EQ(invariant->names.size(), 1u);
  EXPECT_EQ(invariant->names[0].text, "gl_Position");
  const auto* layout = Decl<QualifierDeclaration>(*p, 2);
  ASSERT_NE(layout, nullptr);
  EXPECT_EQ(layout->qualifiers.items[0].layout_ids[0].name.text, "std140");
}

TEST(DeclarationTest, InterfaceBlocksAndLayout) {
  auto p = ParseText(
      "#version 300 es\n"
      "layout(std140, binding = 0) uniform Block { mediump vec4 v; float f[2]; } b[2];\n"
      "uniform Plain { mat4 m; };\n"
      "layout(location = 0) out vec4 color;\n"
      "flat in int id; centroid out float c; smooth out float s;\n");
  ASSERT_TRUE(p->result.diagnostics.empty()) << p->Messages()[0];
  const auto* block = Decl<InterfaceBlock>(*p, 0);
  ASSERT_NE(block, nullptr);
  EXPECT_EQ(block->block_name.text, "Block");
  EXPECT_EQ(block->members.size(), 2u);
  EXPECT_EQ(block->instance_name.text, "b");
  EXPECT_EQ(block->instance_array.size(), 1u);
  ASSERT_EQ(block->qualifiers.items.size(), 2u);
  EXPECT_EQ(block->qualifiers.items[0].layout_ids.size(), 2u);
  EXPECT_NE(block->qualifiers.items[0].layout_ids[1].value, nullptr);
  EXPECT_TRUE(Decl<InterfaceBlock>(*p, 1)->instance_name.Empty());
  const auto* color = Decl<VariableDeclaration>(*p, 2);
  EXPECT_TRUE(color->qualifiers.Has(QualifierKind::kLayout));
  EXPECT_TRUE(color->qualifiers.Has(QualifierKind::kOut));
  EXPECT_TRUE(Decl<VariableDeclaration>(*p, 3)->qualifiers.Has(QualifierKind::kFlat));
}

TEST(DeclarationTest, Es100StorageQualifiers) {
  auto p = ParseText(
      "attribute vec4 pos;\nvarying vec2 uv;\nuniform sampler2D tex;\ninvariant varying vec4 c;\n",
      100);
  ASSERT_TRUE(p->result.diagnostics.empty()) << p->Messages()[0];
  EXPECT_TRUE(Decl<VariableDeclaration>(*p, 0)->qualifiers.Has(QualifierKind::kAttribute));
  EXPECT_TRUE(Decl<VariableDeclaration>(*p, 1)->qualifiers.Has(QualifierKind::kVarying));
  EXPECT_TRUE(Decl<VariableDeclaration>(*p, 3)->qualifiers.Has(QualifierKind::kInvariant));
}

TEST(DeclarationTest, UnknownTypeNameIsADeclarationForSema) {
  auto p = ParseText("Foo bar;\n");
  EXPECT_TRUE(p->result.diagnostics.empty());
  const auto* decl = Decl<VariableDeclaration>(*p, 0);
  ASSERT_NE(decl, nullptr);
  EXPECT_EQ(decl->type->name_kind, TypeNameKind::kUnknown);
}

TEST(DeclarationTest, StructNameIsScoped) {
  // S is a type only inside f, so `S * x;` at the end of g is an expression.
  auto p = ParseText(
      "void f() { struct S { float a; }; S s; }\n"
      "void g() { float S = 1.0, x = 2.0; S * x; }\n");
  ASSERT_TRUE(p->result.diagnostics.empty()) << p->Messages()[0];
  const auto* g = Decl<FunctionDeclaration>(*p, 1);
  EXPECT_EQ(g->body->statements[1]->kind, NodeKind::kExpressionStatement);
}

}  // namespace
}  // namespace shaderport::glsl::testing
