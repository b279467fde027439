// GLSL ES typing rules for operators, swizzles and indexing, as pure functions of
// operand types. Each returns Type::Unknown() when an operand is unknown or the
// operation is not valid GLSL (there are no implicit conversions).
#pragma once

#include <string_view>

#include "glsl/sema/type.h"
#include "glsl/syntax/ast.h"

namespace shaderport::glsl {

Type UnaryResultType(UnaryOp op, const Type& operand);
// `kComma` gives `rhs`.
Type BinaryResultType(BinaryOp op, const Type& lhs, const Type& rhs);
// The binary operator behind a compound assignment (`+=` -> `+`); false for `=`.
bool CompoundAssignOperator(AssignOp op, BinaryOp& binary);

// `v.xyz`, `c.rgba`, `t.st`: one naming set, 1..4 letters within the vector's size.
Type SwizzleType(const Type& object, std::string_view swizzle);
// `a[i]`: an array element, a vector component or a matrix column.
Type IndexResultType(const Type& base);

// The same shape with a float base: int -> float, ivec3 -> vec3. Unknown for other types.
Type IntToFloat(const Type& type);

}  // namespace shaderport::glsl
