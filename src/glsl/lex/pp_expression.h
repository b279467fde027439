// Evaluation of #if / #elif expressions (not public API).
#pragma once

#include <span>

#include "glsl/lex/pp_state.h"

namespace shaderport::glsl {

// Evaluates macro-expanded `tokens` as an integer constant expression with C's
// operators. Errors are reported (only for evaluated operands, so `0 && 1/0` is
// fine) and make the condition false. `directive` locates an empty expression.
bool EvaluateCondition(PpState& state, std::span<const ExpToken> tokens, SourceRange directive);

}  // namespace shaderport::glsl
