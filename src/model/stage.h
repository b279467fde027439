// The pipeline stage a shader runs in: one type for every layer (docs/architecture.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace shaderport::model {

enum class Stage : uint8_t { kVertex, kFragment };

std::string_view StageName(Stage stage);                 // "vertex", "fragment"
std::optional<Stage> ParseStage(std::string_view name);  // also "vert", "frag"

}  // namespace shaderport::model
