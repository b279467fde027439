// Which texture functions each sampler variable of a SPIR-V module is used with.
#pragma once

#include <map>
#include <set>
#include <string>

#include "toolchain/spirv_tools.h"

namespace shaderport::toolchain {

// Sampler variable name -> GLSL ES function names ("texture", "textureLod", "texelFetch",
// "textureSize"...). Best run on a module whose calls are inlined (InlineAllCalls), so that
// every image operation traces back to a global variable; others are not counted.
std::map<std::string, std::set<std::string>> SamplerOperations(const SpirvWords& words);

}  // namespace shaderport::toolchain
