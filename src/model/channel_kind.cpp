#include "model/channel_kind.h"

namespace shaderport::model {

std::string_view ChannelKindName(ChannelKind kind) {
  switch (kind) {
    case ChannelKind::kCube:
      return "cube";
    case ChannelKind::k3D:
      return "3d";
    case ChannelKind::k2D:
      break;
  }
  return "2d";
}

std::optional<ChannelKind> ParseChannelKind(std::string_view name) {
  if (name == "2d") return ChannelKind::k2D;
  if (name == "cube") return ChannelKind::kCube;
  if (name == "3d") return ChannelKind::k3D;
  return std::nullopt;
}

std::string_view SamplerTypeName(ChannelKind kind) {
  switch (kind) {
    case ChannelKind::kCube:
      return "samplerCube";
    case ChannelKind::k3D:
      return "sampler3D";
    case ChannelKind::k2D:
      break;
  }
  return "sampler2D";
}

ChannelKind ChannelKindFromCtype(std::string_view ctype) {
  if (ctype == "cubemap") return ChannelKind::kCube;
  if (ctype == "volume") return ChannelKind::k3D;
  return ChannelKind::k2D;
}

}  // namespace shaderport::model
