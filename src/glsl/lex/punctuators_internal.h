// Punctuator tables shared by the lexer and the token paster (not public API).
#pragma once

#include <string_view>

#include "glsl/lex/token.h"

namespace shaderport::glsl {

// The longest punctuator that starts with c0 c1 c2 (pass '\0' past the end);
// sets *length to its size, or 0 and returns kNone when none matches.
Punct MatchPunctuator(char c0, char c1, char c2, int* length);

// The punctuator spelled exactly `text`, or kNone.
Punct PunctFromSpelling(std::string_view text);

}  // namespace shaderport::glsl
