// How large a SPIR-V module's entry point becomes when every call is inlined, as
// spirv-opt's performance passes do first: a raymarcher that calls its distance
// function from several helpers, each called from several places, grows
// exponentially (one ShaderToy pass: 2,400 instructions, 258,000 once inlined,
// 20 s in spirv-opt). Counted from the call graph without inlining anything.
#pragma once

#include <cstdint>

#include "toolchain/spirv_tools.h"

namespace shaderport::toolchain {

// Instructions of the entry point with every OpFunctionCall replaced by the callee's
// body, recursively; 0 for a module without an entry point. Saturates at UINT64_MAX.
uint64_t InlinedInstructionCount(const SpirvWords& words);

}  // namespace shaderport::toolchain
