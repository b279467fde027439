// SPIRV-Cross as an adapter: HLSL, MSL and ESSL 3.00 from a SPIR-V module. SPIRV-Cross reports
// failures by throwing; nothing escapes this adapter.
#pragma once

#include <string>

#include "toolchain/spirv_tools.h"

namespace shaderport::toolchain {

enum class CrossTarget { kHlsl, kMsl, kEssl300 };

struct CrossOptions {
  int hlsl_shader_model = 50;  // spirv-cross --shader-model
  int msl_version = 20000;     // spirv-cross --msl-version (major*10000 + minor*100 + patch)
};

struct CrossOutcome {
  std::string text;   // "" on failure
  std::string error;  // SPIRV-Cross's message on failure
};

CrossOutcome CrossCompile(const SpirvWords& words, CrossTarget target, const CrossOptions& options);

}  // namespace shaderport::toolchain
