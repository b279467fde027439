// SPIRV-Tools on a module: validation, optimisation (spirv-opt -O / -Os), disassembly.
// All of it for the OpenGL 4.5 environment the SPIR-V leg targets.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shaderport::toolchain {

using SpirvWords = std::vector<uint32_t>;

enum class OptimizeLevel { kPerformance, kSize };  // spirv-opt -O, -Os

// "O" -> kPerformance, "Os" -> kSize, nullopt otherwise.
std::optional<OptimizeLevel> OptimizeLevelFromName(const std::string& name);

// "" when spirv-val would accept `words`, else the validator's messages.
std::string ValidateSpirv(const SpirvWords& words);

struct OptimizeOutcome {
  SpirvWords words;   // empty on failure
  std::string error;  // the optimiser's messages on failure
};
OptimizeOutcome OptimizeSpirv(const SpirvWords& words, OptimizeLevel level);

// spirv-dis text with friendly names and indentation; "" if the module cannot be disassembled.
std::string DisassembleSpirv(const SpirvWords& words);

// Inlines every function call into the entry point, as an aid to analysis (reflect.cpp).
// Returns the input unchanged when inlining fails.
SpirvWords InlineAllCalls(const SpirvWords& words);

}  // namespace shaderport::toolchain
