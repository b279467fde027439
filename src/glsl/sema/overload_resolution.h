// Overload resolution for GLSL ES: there are no implicit conversions, so a call
// matches an overload only when every argument has exactly the parameter's type.
#pragma once

#include <span>
#include <string_view>

#include "glsl/sema/builtins.h"
#include "glsl/sema/type.h"

namespace shaderport::glsl {

enum class ArgumentMatch : uint8_t {
  kExact,      // every argument has the parameter's type
  kUncertain,  // no known argument disagrees, but some argument type is unknown
  kNone,
};

ArgumentMatch MatchArguments(std::span<const Type> parameters, std::span<const Type> arguments);
ArgumentMatch MatchArguments(std::span<const BuiltinParam> parameters,
                             std::span<const Type> arguments);

struct BuiltinCallMatch {
  const BuiltinFunction* function = nullptr;  // nullptr: no match (or several uncertain ones)
  bool uncertain = false;  // matched only because some argument types are unknown
  bool available = true;   // false: the overload exists only in another version or stage
};

// Resolves a call to the built-in `name`: first among the overloads available in
// (version, stage), then among all of them (so that e.g. texture2D in a 3.00 shader still
// gets a type, marked unavailable). Several uncertain candidates give no match unless they
// all return the same type, in which case the first is returned.
BuiltinCallMatch ResolveBuiltinCall(std::string_view name, std::span<const Type> arguments,
                                    int version, model::Stage stage);
// The same over `overloads`, the BuiltinOverloadList of the name (for a caller that has it).
BuiltinCallMatch ResolveBuiltinCall(std::span<const BuiltinFunction* const> overloads,
                                    std::span<const Type> arguments, int version,
                                    model::Stage stage);

}  // namespace shaderport::glsl
