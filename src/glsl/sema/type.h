// The GLSL ES type model: scalars, vectors, matrices, samplers, structs and
// one-dimensional arrays of them, plus `unknown` for what the model cannot tell.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace shaderport::glsl {

class StructTable;

enum class BaseType : uint8_t {
  kUnknown,  // the model could not tell (errors, unsupported constructs)
  kVoid,
  kBool,
  kInt,
  kUint,
  kFloat,
  kSampler,
  kStruct,
};

enum class SamplerDim : uint8_t { kNone, k2D, k3D, kCube, k2DArray };

// A value type, cheap to copy, compared field by field.
struct Type {
  static constexpr int32_t kNotArray = 0;
  static constexpr int32_t kUnsizedArray = -1;

  BaseType base = BaseType::kUnknown;
  uint8_t rows = 1;     // components of a vector, or of each matrix column; 1 for scalars
  uint8_t columns = 1;  // matrix columns; 1 for everything that is not a matrix
  SamplerDim sampler_dim = SamplerDim::kNone;
  BaseType sampled = BaseType::kUnknown;  // samplers: float, int or uint texels
  bool shadow = false;                    // samplers: a depth-comparison sampler
  uint32_t struct_id = 0;                 // structs: index into a StructTable
  int32_t array_size = kNotArray;         // > 0 sized, kUnsizedArray, or kNotArray

  static constexpr Type Unknown() { return {}; }
  static constexpr Type Void() { return Type{.base = BaseType::kVoid}; }
  static constexpr Type Scalar(BaseType base) { return Type{.base = base}; }
  static constexpr Type Bool() { return Scalar(BaseType::kBool); }
  static constexpr Type Int() { return Scalar(BaseType::kInt); }
  static constexpr Type Uint() { return Scalar(BaseType::kUint); }
  static constexpr Type Float() { return Scalar(BaseType::kFloat); }
  // `size` 1 gives the scalar.
  static constexpr Type Vector(BaseType base, int size) {
    return Type{.base = base, .rows = static_cast<uint8_t>(size)};
  }
  static constexpr Type Matrix(int columns, int rows) {
    return Type{.base = BaseType::kFloat,
                .rows = static_cast<uint8_t>(rows),
                .columns = static_cast<uint8_t>(columns)};
  }
  static constexpr Type Sampler(SamplerDim dim, BaseType sampled = BaseType::kFloat,
                                bool shadow = false) {
    return Type{
        .base = BaseType::kSampler, .sampler_dim = dim, .sampled = sampled, .shadow = shadow};
  }
  static constexpr Type Struct(uint32_t id) {
    return Type{.base = BaseType::kStruct, .struct_id = id};
  }

  bool IsUnknown() const { return base == BaseType::kUnknown; }
  bool IsVoid() const { return base == BaseType::kVoid; }
  bool IsArray() const { return array_size != kNotArray; }
  // The following look at the element type only when the type is not an array.
  bool IsScalar() const { return !IsArray() && IsBasicData() && rows == 1 && columns == 1; }
  bool IsVector() const { return !IsArray() && IsBasicData() && rows > 1 && columns == 1; }
  bool IsMatrix() const { return !IsArray() && columns > 1; }
  bool IsSampler() const { return !IsArray() && base == BaseType::kSampler; }
  bool IsStruct() const { return !IsArray() && base == BaseType::kStruct; }
  // bool/int/uint/float scalars, vectors and matrices (arrays included).
  bool IsBasicData() const {
    return base == BaseType::kBool || base == BaseType::kInt || base == BaseType::kUint ||
           base == BaseType::kFloat;
  }
  bool IsNumeric() const { return !IsArray() && IsBasicData() && base != BaseType::kBool; }
  bool IsFloating() const { return !IsArray() && base == BaseType::kFloat; }
  bool IsIntegral() const {
    return !IsArray() && (base == BaseType::kInt || base == BaseType::kUint) && columns == 1;
  }
  bool IsBoolean() const { return !IsArray() && base == BaseType::kBool && columns == 1; }
  // Number of scalar components of a scalar, vector or matrix (0 otherwise).
  int ComponentCount() const { return IsBasicData() && !IsArray() ? rows * columns : 0; }

  // The type of one element of an array (the type itself when not an array).
  Type Element() const {
    Type t = *this;
    t.array_size = kNotArray;
    return t;
  }
  Type ArrayOf(int32_t size) const {
    Type t = *this;
    t.array_size = size;
    return t;
  }
  // The scalar type with the same base (float for a matrix).
  Type Component() const { return Scalar(base); }
  // A vector (or scalar, for n == 1) of this type's base.
  Type WithRows(int n) const { return Vector(base, n); }
  // The type of one column of a matrix.
  Type Column() const { return Vector(BaseType::kFloat, rows); }

  friend bool operator==(const Type&, const Type&) = default;
};

// Spells a type as GLSL writes it: `vec3`, `mat2x3`, `float[3]`, `isampler2D`, the struct's
// name (from `structs`, else `struct#N`), `unknown`.
std::string Spell(const Type& type, const StructTable* structs = nullptr);

// The type named by a built-in type keyword (`vec3`, `mat4x2`, `usampler3D`, `void`...), or
// nothing for any other word. Version availability is the caller's business.
std::optional<Type> BuiltinTypeByName(std::string_view name);

// Whether the built-in type keyword exists in GLSL ES `version` (100 or 300).
bool BuiltinTypeAvailable(const Type& type, int version);

}  // namespace shaderport::glsl
