// The WebGL context a shader runs in (`--target`), apart from the GLSL ES version its
// #version line picks: a WebGL2 context also compiles GLSL ES 1.00 code.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace shaderport::model {

enum class Target : uint8_t { kWebGL1, kWebGL2 };

std::string_view TargetName(Target target);  // "webgl1", "webgl2"
std::optional<Target> ParseTarget(std::string_view name);

}  // namespace shaderport::model
