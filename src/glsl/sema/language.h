// Which language the analysis follows: GLSL ES version and shader stage.
#pragma once

#include <cstdint>

#include "model/stage.h"

namespace shaderport::glsl {

// GLSL ES versions the model knows. Anything at or above 300 is treated as 3.00.
inline constexpr int kEssl100 = 100;
inline constexpr int kEssl300 = 300;

// Bit sets used by the built-in tables.
enum VersionBits : uint8_t { kVersion100 = 1, kVersion300 = 2, kAllVersions = 3 };
enum StageBits : uint8_t { kVertexStage = 1, kFragmentStage = 2, kAllStages = 3 };

inline uint8_t VersionBit(int version) { return version >= kEssl300 ? kVersion300 : kVersion100; }
inline uint8_t StageBit(model::Stage stage) {
  return stage == model::Stage::kVertex ? kVertexStage : kFragmentStage;
}

}  // namespace shaderport::glsl
