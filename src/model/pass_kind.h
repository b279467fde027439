// The ShaderToy tab a piece of code stands for; it decides the site's generated main().
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace shaderport::model {

// Common has no pass of its own: the site compiles it inside each pass, so code that
// composes a pass treats kCommon as an Image pass (validate/shadertoy_contract.h).
enum class PassKind : uint8_t { kImage, kBuffer, kCube, kSound, kCommon };

// "image", "buffer", "cube", "sound", "common": the `type` of a pass in a ShaderToy
// JSON export. ParsePassKind takes exactly these (nullopt otherwise).
std::string_view PassKindName(PassKind kind);
std::optional<PassKind> ParsePassKind(std::string_view name);

}  // namespace shaderport::model
