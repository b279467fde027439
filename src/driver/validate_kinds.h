// The driver's view of a file (dialect, stage, ShaderToy pass) in the terms
// the validation layer takes.
#pragma once

#include "driver/dialect.h"
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

inline validate::Stage ToValidateStage(Stage stage) {
  return stage == Stage::kVertex ? validate::Stage::kVertex : validate::Stage::kFragment;
}

}  // namespace shaderport::driver
