// `--emit reflect`: what a shader's SPIR-V module declares and uses, as JSON
// (docs/reflect.schema.json).
#pragma once

#include <string>

#include "toolchain/emit.h"
#include "toolchain/spirv_tools.h"

namespace shaderport::toolchain {

struct ReflectOutcome {
  std::string json;   // pretty-printed, ends with a newline; "" on failure
  std::string error;  // SPIRV-Cross's message on failure
};

// `words` should be the unoptimised module, which keeps every declaration and its name.
// With `shadertoy`, also reports how iChannel0..3 and the site's uniforms are used.
ReflectOutcome Reflect(const SpirvWords& words, model::Stage stage, bool shadertoy);

}  // namespace shaderport::toolchain
