#include "glsl/sema/type.h"

#include <gtest/gtest.h>

#include "glsl/sema/struct_table.h"

namespace shaderport::glsl {
namespace {

TEST(TypeTest, SpellsAsGlslWrites) {
  EXPECT_EQ(Spell(Type::Float()), "float");
  EXPECT_EQ(Spell(Type::Vector(BaseType::kFloat, 3)), "vec3");
  EXPECT_EQ(Spell(Type::Vector(BaseType::kBool, 2)), "bvec2");
  EXPECT_EQ(Spell(Type::Vector(BaseType::kUint, 4)), "uvec4");
  EXPECT_EQ(Spell(Type::Matrix(3, 3)), "mat3");
  EXPECT_EQ(Spell(Type::Matrix(2, 3)), "mat2x3");
  EXPECT_EQ(Spell(Type::Float().ArrayOf(3)), "float[3]");
  EXPECT_EQ(Spell(Type::Vector(BaseType::kFloat, 4).ArrayOf(Type::kUnsizedArray)), "vec4[]");
  EXPECT_EQ(Spell(Type::Sampler(SamplerDim::k2DArray, BaseType::kUint)), "usampler2DArray");
  EXPECT_EQ(Spell(Type::Sampler(SamplerDim::kCube, BaseType::kFloat, true)), "samplerCubeShadow");
  EXPECT_EQ(Spell(Type::Unknown()), "unknown");
  EXPECT_EQ(Spell(Type::Void()), "void");
  StructTable structs;
  uint32_t id = structs.Add({"Light", {{"pos", Type::Vector(BaseType::kFloat, 3)}}, kNoNode});
  EXPECT_EQ(Spell(Type::Struct(id), &structs), "Light");
  EXPECT_EQ(Spell(Type::Struct(id).ArrayOf(2), &structs), "Light[2]");
  EXPECT_EQ(Spell(Type::Struct(id)), "struct#1");
}

TEST(TypeTest, ParsesEveryBuiltinTypeName) {
  for (const char* name : {"void",
                           "bool",
                           "int",
                           "uint",
                           "float",
                           "vec2",
                           "vec3",
                           "vec4",
                           "bvec2",
                           "ivec3",
                           "uvec4",
                           "mat2",
                           "mat3",
                           "mat4",
                           "mat2x3",
                           "mat4x2",
                           "mat3x4",
                           "sampler2D",
                           "samplerCube",
                           "sampler3D",
                           "sampler2DShadow",
                           "samplerCubeShadow",
                           "sampler2DArray",
                           "sampler2DArrayShadow",
                           "isampler2D",
                           "isampler3D",
                           "isamplerCube",
                           "isampler2DArray",
                           "usampler2D",
                           "usampler3D",
                           "usamplerCube",
                           "usampler2DArray"}) {
    std::optional<Type> t = BuiltinTypeByName(name);
    ASSERT_TRUE(t.has_value()) << name;
    EXPECT_EQ(Spell(*t), name);
  }
  EXPECT_EQ(BuiltinTypeByName("mat3x3"), Type::Matrix(3, 3));
  for (const char* name : {"vec1", "vec5", "mat5", "mat2x", "dvec2", "S", "sampler1D", ""}) {
    EXPECT_FALSE(BuiltinTypeByName(name).has_value()) << name;
  }
}

TEST(TypeTest, Predicates) {
  Type v3 = Type::Vector(BaseType::kFloat, 3);
  EXPECT_TRUE(v3.IsVector());
  EXPECT_FALSE(v3.IsScalar());
  EXPECT_EQ(v3.ComponentCount(), 3);
  EXPECT_EQ(v3.Component(), Type::Float());
  Type m = Type::Matrix(2, 4);
  EXPECT_TRUE(m.IsMatrix());
  EXPECT_EQ(m.ComponentCount(), 8);
  EXPECT_EQ(m.Column(), Type::Vector(BaseType::kFloat, 4));
  Type arr = v3.ArrayOf(4);
  EXPECT_TRUE(arr.IsArray());
  EXPECT_FALSE(arr.IsVector());
  EXPECT_EQ(arr.Element(), v3);
  EXPECT_TRUE(Type::Int().IsIntegral());
  EXPECT_FALSE(Type::Bool().IsNumeric());
  EXPECT_TRUE(Type::Bool().IsBoolean());
}

TEST(TypeTest, VersionAvailability) {
  EXPECT_TRUE(BuiltinTypeAvailable(Type::Matrix(3, 3), 100));
  EXPECT_FALSE(BuiltinTypeAvailable(Type::Matrix(2, 3), 100));
  EXPECT_FALSE(BuiltinTypeAvailable(Type::Uint(), 100));
  EXPECT_FALSE(BuiltinTypeAvailable(Type::Sampler(SamplerDim::k3D), 100));
  EXPECT_TRUE(BuiltinTypeAvailable(Type::Sampler(SamplerDim::kCube), 100));
  EXPECT_TRUE(BuiltinTypeAvailable(Type::Sampler(SamplerDim::k3D, BaseType::kInt), 300));
}

}  // namespace
}  // namespace shaderport::glsl
