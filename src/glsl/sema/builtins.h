// The built-in functions and variables of GLSL ES 1.00 and 3.00, read from
// builtin_functions.def and builtin_variables.def with their families expanded.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "glsl/sema/language.h"
#include "glsl/sema/type.h"

namespace shaderport::glsl {

enum class ParamQualifier : uint8_t { kIn, kOut, kInOut };

struct BuiltinParam {
  Type type;
  ParamQualifier qualifier = ParamQualifier::kIn;
  bool must_be_constant = false;  // e.g. texture offsets
};

// One overload, after family expansion (genType -> float, vec2, vec3, vec4...).
struct BuiltinFunction {
  std::string name;
  Type return_type;
  std::vector<BuiltinParam> params;
  uint8_t versions = kAllVersions;  // VersionBits
  uint8_t stages = kAllStages;      // StageBits
  std::string_view extension;       // ESSL 1.00 #extension enabling it; empty for core
  uint32_t row = 0;                 // the .def row it came from (0-based)

  bool AvailableIn(int version, model::Stage stage) const {
    return (versions & VersionBit(version)) != 0 && (stages & StageBit(stage)) != 0;
  }
};

enum class BuiltinStorage : uint8_t { kIn, kOut, kUniform, kConst };

struct BuiltinVariable {
  std::string name;
  Type type;  // struct types refer to the ids StructTable predefines
  BuiltinStorage storage = BuiltinStorage::kIn;
  uint8_t versions = kAllVersions;
  uint8_t stages = kAllStages;
  std::string_view extension;
  int value = 0;  // kConst: the minimum value the spec guarantees

  bool AvailableIn(int version, model::Stage stage) const {
    return (versions & VersionBit(version)) != 0 && (stages & StageBit(stage)) != 0;
  }
};

// Every overload of every built-in function, in .def order (built once, thread-safe).
std::span<const BuiltinFunction> AllBuiltinFunctions();
std::span<const BuiltinVariable> AllBuiltinVariables();

// Every overload named `name`, whatever its availability; empty when there is none.
std::vector<const BuiltinFunction*> BuiltinOverloads(std::string_view name);
// The same overloads, without a copy: the list lives as long as the program.
std::span<const BuiltinFunction* const> BuiltinOverloadList(std::string_view name);
// The variable named `name` available in (version, stage), else nullptr. Extension rows count
// as available: whether the extension is enabled is for a rule to check.
const BuiltinVariable* FindBuiltinVariable(std::string_view name, int version, model::Stage stage);
// Whether some built-in function is called `name` in any version or stage.
bool IsBuiltinFunctionName(std::string_view name);

// Rows in the .def files (a table test checks every row yields entries).
size_t BuiltinFunctionRowCount();
size_t BuiltinVariableRowCount();

}  // namespace shaderport::glsl
