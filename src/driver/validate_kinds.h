// The driver's view of a file (dialect, stage, ShaderToy pass) in the terms
// the validation layer takes.
#pragma once

#include <string_view>

#include "driver/dialect.h"
#include "rule/rule_context.h"
#include "validate/glslang_runner.h"
#include "validate/shadertoy_contract.h"

namespace shaderport::driver {

// Common code has no pass of its own: it is compiled as an Image pass would see it.
inline validate::PassType ToPassType(ShaderToyPass pass) {
  switch (pass) {
    case ShaderToyPass::kCubemap:
      return validate::PassType::kCube;
    case ShaderToyPass::kSound:
      return validate::PassType::kSound;
    case ShaderToyPass::kBuffer:
      return validate::PassType::kBuffer;
    case ShaderToyPass::kImage:
    case ShaderToyPass::kCommon:
      return validate::PassType::kImage;
  }
  return validate::PassType::kImage;
}

// "2d", "cube", "3d": as --channel and explain-file spell a channel's sampler type.
inline std::string_view ChannelTypeName(validate::ChannelType type) {
  switch (type) {
    case validate::ChannelType::kCube:
      return "cube";
    case validate::ChannelType::k3D:
      return "3d";
    case validate::ChannelType::k2D:
      break;
  }
  return "2d";
}

// The rules' name for a decided channel type (a decided channel is never kAuto).
inline rule::ChannelKind ToChannelKind(validate::ChannelType type) {
  switch (type) {
    case validate::ChannelType::kCube:
      return rule::ChannelKind::kCube;
    case validate::ChannelType::k3D:
      return rule::ChannelKind::k3D;
    case validate::ChannelType::k2D:
      break;
  }
  return rule::ChannelKind::k2D;
}

}  // namespace shaderport::driver
