#include "model/target.h"

namespace shaderport::model {

std::string_view TargetName(Target target) {
  return target == Target::kWebGL1 ? "webgl1" : "webgl2";
}

std::optional<Target> ParseTarget(std::string_view name) {
  if (name == "webgl1") return Target::kWebGL1;
  if (name == "webgl2") return Target::kWebGL2;
  return std::nullopt;
}

}  // namespace shaderport::model
