#include "model/pass_kind.h"

namespace shaderport::model {

std::string_view PassKindName(PassKind kind) {
  switch (kind) {
    case PassKind::kBuffer:
      return "buffer";
    case PassKind::kCube:
      return "cube";
    case PassKind::kSound:
      return "sound";
    case PassKind::kCommon:
      return "common";
    case PassKind::kImage:
      break;
  }
  return "image";
}

std::optional<PassKind> ParsePassKind(std::string_view name) {
  if (name == "image") return PassKind::kImage;
  if (name == "buffer") return PassKind::kBuffer;
  if (name == "cube") return PassKind::kCube;
  if (name == "sound") return PassKind::kSound;
  if (name == "common") return PassKind::kCommon;
  return std::nullopt;
}

}  // namespace shaderport::model
