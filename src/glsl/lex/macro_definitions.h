// #define, #undef and predefined macros (not public API).
#pragma once

#include <span>
#include <string_view>

#include "glsl/lex/pp_state.h"

namespace shaderport::glsl {

// `line` holds the tokens after the word "define". Reports problems and leaves the
// table unchanged on error. Checks ESSL's reserved names and redefinitions.
void DefineMacro(PpState& state, const SourceFile& file, std::span<const Token> line,
                 SourceRange directive);

// `line` holds the tokens after the word "undef".
void UndefineMacro(PpState& state, const SourceFile& file, std::span<const Token> line,
                   SourceRange directive);

// GL_ES, __LINE__, __FILE__, __VERSION__ and the caller's "NAME" / "NAME=value" macros.
void AddPredefinedMacros(PpState& state, std::span<const std::string> predefined);

}  // namespace shaderport::glsl
