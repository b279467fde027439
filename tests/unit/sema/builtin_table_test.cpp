#include <gtest/gtest.h>

#include <set>

#include "glsl/sema/builtins.h"
#include "glsl/sema/overload_resolution.h"

namespace shaderport::glsl {
namespace {

const Type kFloat = Type::Float();
const Type kInt = Type::Int();
const Type kVec2 = Type::Vector(BaseType::kFloat, 2);
const Type kVec3 = Type::Vector(BaseType::kFloat, 3);
const Type kVec4 = Type::Vector(BaseType::kFloat, 4);
const Type kSampler2D = Type::Sampler(SamplerDim::k2D);

TEST(BuiltinTableTest, EveryRowExpands) {
  std::set<uint32_t> rows;
  for (const BuiltinFunction& f : AllBuiltinFunctions()) rows.insert(f.row);
  EXPECT_EQ(rows.size(), BuiltinFunctionRowCount());
  EXPECT_EQ(AllBuiltinVariables().size(), BuiltinVariableRowCount());
  EXPECT_GT(AllBuiltinFunctions().size(), 650u);
}

TEST(BuiltinTableTest, FamiliesExpand) {
  // genType: float, vec2, vec3, vec4.
  EXPECT_EQ(BuiltinOverloads("sin").size(), 4u);
  // mod: (genType, float) and (genType, genType), the float/float pair twice.
  EXPECT_EQ(BuiltinOverloads("mod").size(), 8u);
  // matrixCompMult: 3 square (1.00) + 9 (3.00).
  EXPECT_EQ(BuiltinOverloads("matrixCompMult").size(), 12u);
  // texture: g x {2D, 3D, Cube, 2DArray} + 2 shadow with/without bias, + 2DArrayShadow.
  EXPECT_EQ(BuiltinOverloads("texture").size(), 3u * 4u * 2u + 2u * 2u + 1u);
  EXPECT_TRUE(BuiltinOverloads("nosuchfunction").empty());
  EXPECT_TRUE(IsBuiltinFunctionName("texelFetchOffset"));
}

TEST(BuiltinTableTest, ExactMatchOnly) {
  BuiltinCallMatch m =
      ResolveBuiltinCall("pow", std::vector{kFloat, kInt}, 300, model::Stage::kFragment);
  EXPECT_EQ(m.function, nullptr);
  m = ResolveBuiltinCall("pow", std::vector{kVec3, kVec3}, 300, model::Stage::kFragment);
  ASSERT_NE(m.function, nullptr);
  EXPECT_EQ(m.function->return_type, kVec3);
  m = ResolveBuiltinCall("mix", std::vector{kVec3, kVec3, kFloat}, 100, model::Stage::kVertex);
  ASSERT_NE(m.function, nullptr);
  EXPECT_EQ(m.function->return_type, kVec3);
  m = ResolveBuiltinCall("dot", std::vector{kVec2, kVec2}, 100, model::Stage::kVertex);
  ASSERT_NE(m.function, nullptr);
  EXPECT_EQ(m.function->return_type, kFloat);
  m = ResolveBuiltinCall("min", std::vector{kInt, kInt}, 300, model::Stage::kFragment);
  ASSERT_NE(m.function, nullptr);
  EXPECT_EQ(m.function->return_type, kInt);
  // int min exists only in 3.00: in 1.00 it resolves but is marked unavailable.
  m = ResolveBuiltinCall("min", std::vector{kInt, kInt}, 100, model::Stage::kFragment);
  ASSERT_NE(m.function, nullptr);
  EXPECT_FALSE(m.available);
}

TEST(BuiltinTableTest, TextureLookups) {
  BuiltinCallMatch m =
      ResolveBuiltinCall("texture", std::vector{kSampler2D, kVec2}, 300, model::Stage::kFragment);
  ASSERT_NE(m.function, nullptr);
  EXPECT_EQ(m.function->return_type, kVec4);
  m = ResolveBuiltinCall("texture",
                         std::vector{Type::Sampler(SamplerDim::k2D, BaseType::kInt), kVec2, kFloat},
                         300, model::Stage::kFragment);
  ASSERT_NE(m.function, nullptr);
  EXPECT_EQ(m.function->return_type, Type::Vector(BaseType::kInt, 4));
  // Bias forms are fragment-only.
  m = ResolveBuiltinCall("texture2D", std::vector{kSampler2D, kVec2, kFloat}, 100,
                         model::Stage::kVertex);
  ASSERT_NE(m.function, nullptr);
  EXPECT_FALSE(m.available);
  // texture2D is gone in 3.00 but still typed.
  m = ResolveBuiltinCall("texture2D", std::vector{kSampler2D, kVec2}, 300, model::Stage::kFragment);
  ASSERT_NE(m.function, nullptr);
  EXPECT_FALSE(m.available);
  EXPECT_EQ(m.function->return_type, kVec4);
  m = ResolveBuiltinCall("textureSize", std::vector{Type::Sampler(SamplerDim::k3D), kInt}, 300,
                         model::Stage::kVertex);
  ASSERT_NE(m.function, nullptr);
  EXPECT_EQ(m.function->return_type, Type::Vector(BaseType::kInt, 3));
}

TEST(BuiltinTableTest, UnknownArgumentsResolveWhenUnambiguous) {
  BuiltinCallMatch m =
      ResolveBuiltinCall("length", std::vector{Type::Unknown()}, 300, model::Stage::kFragment);
  ASSERT_NE(m.function, nullptr);  // every length() returns float
  EXPECT_TRUE(m.uncertain);
  EXPECT_EQ(m.function->return_type, kFloat);
  m = ResolveBuiltinCall("normalize", std::vector{Type::Unknown()}, 300, model::Stage::kFragment);
  EXPECT_EQ(m.function, nullptr);
  m = ResolveBuiltinCall("cross", std::vector{Type::Unknown(), kVec3}, 300,
                         model::Stage::kFragment);
  ASSERT_NE(m.function, nullptr);
  EXPECT_EQ(m.function->return_type, kVec3);
}

TEST(BuiltinTableTest, Variables) {
  const BuiltinVariable* v = FindBuiltinVariable("gl_FragColor", 100, model::Stage::kFragment);
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->type, kVec4);
  EXPECT_EQ(FindBuiltinVariable("gl_FragColor", 300, model::Stage::kFragment), nullptr);
  EXPECT_EQ(FindBuiltinVariable("gl_FragColor", 100, model::Stage::kVertex), nullptr);
  v = FindBuiltinVariable("gl_MaxDrawBuffers", 300, model::Stage::kVertex);
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->value, 4);
  EXPECT_EQ(v->storage, BuiltinStorage::kConst);
  v = FindBuiltinVariable("gl_FragData", 100, model::Stage::kFragment);
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(Spell(v->type), "vec4[]");
  EXPECT_NE(FindBuiltinVariable("gl_VertexID", 300, model::Stage::kVertex), nullptr);
  EXPECT_EQ(FindBuiltinVariable("gl_VertexID", 100, model::Stage::kVertex), nullptr);
  EXPECT_NE(FindBuiltinVariable("gl_DepthRange", 100, model::Stage::kFragment), nullptr);
}

}  // namespace
}  // namespace shaderport::glsl
