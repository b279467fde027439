// Macro expansion with rescanning, as in C (not public API): function-like
// calls, argument pre-expansion, `##`, built-in macros and, inside #if, `defined`.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "glsl/lex/pp_state.h"

namespace shaderport::glsl {

// Fully expands `input`. `in_if_expression` makes `defined X` / `defined(X)` a 0 or 1.
// `depth` counts the argument pre-expansions this call is nested in.
std::vector<ExpToken> ExpandMacros(PpState& state, std::vector<ExpToken> input,
                                   bool in_if_expression, uint32_t depth = 0);

// The same outside #if for lexed tokens of `file`, appending the expanded tokens to
// `out`: a run of text goes into the preprocessor's output with no list of input or of
// expanded tokens between, each token converted when the expansion reaches it.
void ExpandMacrosInto(PpState& state, const SourceFile& file, std::span<const Token> source,
                      bool file_has_backslash, std::vector<PpToken>& out);

// Joins two tokens into one with `##`; false (and no change) when the result is not one token.
bool PasteTokens(PpState& state, const PpToken& left, const PpToken& right, PpToken* pasted);

}  // namespace shaderport::glsl
