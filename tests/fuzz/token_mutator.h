// A structure-aware mutator for the GLSL text targets: besides libFuzzer's byte
// mutations it cuts inputs at token boundaries and splices in token runs taken
// from real shaders (the corpus inputs it has seen), so mutants stay mostly
// GLSL-shaped and reach the rules and glslang instead of dying in the lexer.
//
// A target opts in by linking token_mutator.cpp, which defines
// LLVMFuzzerCustomMutator and LLVMFuzzerCustomCrossOver.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace shaderport::fuzz {

// Splits GLSL-ish text into tokens that concatenate back to `text`: whitespace
// runs, identifiers, numbers, comments, preprocessor lines (with their `\`
// continuations), operators (longest match) and single other bytes.
std::vector<std::string_view> TokenizeGlsl(std::string_view text);

// One token-level mutation of `text` driven by `seed`; `donors` are token runs to
// splice in (may be empty). The result is at most `max_size` bytes.
std::string MutateTokens(std::string_view text, const std::vector<std::string>& donors,
                         uint32_t seed, size_t max_size);

// Prefix of `first` up to a token boundary, then a token run of `second`, then the
// rest of `first` from another boundary; at most `max_size` bytes.
std::string CrossOverTokens(std::string_view first, std::string_view second, uint32_t seed,
                            size_t max_size);

}  // namespace shaderport::fuzz
