// Token-level facts about user code that glslang's log does not give: columns,
// unfinished constructs, and inputs known to crash glslang.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "glsl/lex/lexer.h"
#include "source/source_file.h"

namespace shaderport::validate {

// Where glslang's message about `token` on 1-based `line` points: the first
// identifier or punctuator token on that line spelled `token`; when there is none
// (glslang quotes words like 'assign' or '', or the token came from a macro), the
// line from its first to its last non-blank byte.
SourceRange LocateOnLine(const SourceFile& file, const glsl::LexedFile& lexed, uint32_t line,
                         std::string_view token);

// Brace and #if nesting left open at the end of one file.
struct OpenConstructs {
  int32_t braces = 0;
  int32_t parens = 0;
  int32_t conditionals = 0;
  bool Any() const { return braces > 0 || parens > 0 || conditionals > 0; }
  OpenConstructs& operator+=(const OpenConstructs& o) {
    braces += o.braces;
    parens += o.parens;
    conditionals += o.conditionals;
    return *this;
  }
};
OpenConstructs CountOpenConstructs(const glsl::LexedFile& lexed);

// True when a #define body opens more parentheses than it closes. An incomplete
// macro invocation inside a macro expansion can make glslang 12 recurse forever
// (WebGL CTS macro-expansion-tricky.html); such input is validated out of process.
bool HasUnbalancedMacroBody(const glsl::LexedFile& lexed);

// True when some #define body holds more `open` than `close` punctuators (a '{' whose
// '}' was lost from a multi-line macro): its expansions leave the code unclosed.
bool MacroBodyOpens(const glsl::LexedFile& lexed, glsl::Punct open, glsl::Punct close);

// A macro the user's code leaves defined: its name token.
struct UserMacro {
  FileId file = kNoFile;
  std::string_view name;
  uint32_t begin = 0;
  uint32_t end = 0;
};

// The macros still defined after `lexed`'s last line (#define, less #undef), in
// file order, ignoring #if: a macro defined on an inactive branch is kept too,
// which only matters when glslang already reports an error where it is used.
// Definitions in `defined` are replaced or removed by this file's own.
void CollectUserMacros(const glsl::LexedFile& lexed, FileId file, std::vector<UserMacro>& defined);

// The last token of `lexed` that is not part of a directive (e.g. a `;` or `}`
// that glslang only complains about once it sees the text that follows); nullptr
// when there is none.
const glsl::Token* LastCodeToken(const glsl::LexedFile& lexed);

// The first token of `lexed` that is not part of a directive; nullptr when none.
const glsl::Token* FirstCodeToken(const glsl::LexedFile& lexed);

// The 1-based line of the first token of `lexed` that is not part of a directive
// (0 when there is none).
uint32_t FirstCodeLine(const SourceFile& file, const glsl::LexedFile& lexed);

}  // namespace shaderport::validate
