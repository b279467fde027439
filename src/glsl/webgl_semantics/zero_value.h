// The GLSL spelling of a type's zero value (`0.0`, `vec3(0.0)`, `S(0.0, ivec2(0))`,
// `float[2](0.0, 0.0)`), as ANGLE's CreateZeroNode builds it.
#pragma once

#include <optional>
#include <string>

#include "glsl/sema/struct_table.h"
#include "glsl/sema/type.h"

namespace shaderport::glsl {

// Longest array spelled as a constructor; longer ones are initialised in a loop.
inline constexpr int32_t kMaxZeroConstructorElements = 64;

// Nothing for samplers, unknown types, anonymous structs, unsized arrays, arrays in
// GLSL ES 1.00 (no array constructors) and arrays longer than the limit above.
std::optional<std::string> ZeroValue(const Type& type, const StructTable& structs, int version);

}  // namespace shaderport::glsl
