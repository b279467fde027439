// The SPIR-V leg: glslang compiles a validated ESSL 3.00 shader to SPIR-V as 310 es.
#pragma once

#include <cstdint>
#include <vector>

#include "diag/diagnostic.h"
#include "source/source_file.h"
#include "toolchain/emit.h"

namespace shaderport::toolchain {

struct SpirvCompilation {
  std::vector<uint32_t> words;  // empty when diagnostics has errors
  DiagnosticList diagnostics;
};

// glslang refuses SPIR-V from ES shaders older than 310, so the shader is compiled with its
// version forced to `310 es` (line numbers stay those of `file`), for an OpenGL client with
// automatic locations and bindings: plain uniforms keep their names (toolchain-facts.md §1).
// A failure there is `spirv/leg-limitation` when the text is valid ESSL 3.00 (310 es reserves
// more words) and `spirv/invalid-input` when it is not.
SpirvCompilation CompileToSpirv(const SourceFile& file, model::Stage stage);

}  // namespace shaderport::toolchain
