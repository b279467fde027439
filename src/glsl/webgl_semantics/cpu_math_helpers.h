// Internal to the math helpers: the table of helpers (cpu_math_library.cpp) that
// cpu_math_definitions.cpp turns into GLSL.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

namespace shaderport::glsl {

// How the helper's float definition extends to vectors.
enum class Shape : uint8_t {
  kUnary,      // genType f(genType): componentwise
  kBinary,     // genType f(genType, genType): componentwise
  kMinMax,     // genType f(genType, genType) and (genType, float): componentwise
  kMix,        // genType f(genType, genType, genType) and (genType, genType, float)
  kReduction,  // float f(genType[, genType]): written for each size below
  kGeometric,  // genType f(genType, ...): written for each size below
  kInternal,   // float only, called by other helpers
  kFromUint,   // float f(uint) and vecN f(uvecN): componentwise
};

struct Helper {
  std::string_view builtin;  // GLSL name, or an internal name
  Shape shape;
  std::vector<std::string_view> calls;  // other helpers used
  // float definition; for kReduction/kGeometric: `@` is the type, `#` the body part
  // that repeats per component (see ForSize).
  std::string_view text;
  std::string_view float_text = {};  // kReduction: the float overload (no swizzles on floats)
  // The vector overloads written on whole vectors (`@` vecN, `$` ivecN, `%` uvecN),
  // each component computed as the float definition computes it; without, a vector
  // overload calls the float one per component, which costs Mesa a call each.
  std::string_view vector_text = {};
};

// Every helper, each after nothing in particular (definitions order them).
const std::array<Helper, 37>& CpuMathHelpers();
// The helper for a built-in or internal name, or nullptr.
const Helper* FindCpuMathHelper(std::string_view name);

}  // namespace shaderport::glsl
