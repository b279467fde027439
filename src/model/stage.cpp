#include "model/stage.h"

namespace shaderport::model {

std::string_view StageName(Stage stage) { return stage == Stage::kVertex ? "vertex" : "fragment"; }

std::optional<Stage> ParseStage(std::string_view name) {
  if (name == "vertex" || name == "vert") return Stage::kVertex;
  if (name == "fragment" || name == "frag") return Stage::kFragment;
  return std::nullopt;
}

}  // namespace shaderport::model
