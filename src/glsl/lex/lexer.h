// The lossless GLSL ES lexer: every byte of the input ends up in a token or in
// trivia, so Reconstruct() gives back the input exactly, whatever it holds.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "glsl/lex/token.h"
#include "source/source_file.h"

namespace shaderport::glsl {

struct LexedFile {
  // Ends with one kEndOfFile token whose leading trivia are the file's trailing trivia.
  std::vector<Token> tokens;
  std::vector<Trivia> trivia;
  DiagnosticList diagnostics;
};

// Never fails: bytes that start no token become kInvalid tokens with a diagnostic.
LexedFile Lex(const SourceFile& file);

// Joins every token's leading trivia and text; equals file.Text() for any input.
std::string Reconstruct(const SourceFile& file, const LexedFile& lexed);

// One line per token, "line:col kind 'text'", with non-printable bytes escaped.
std::string DumpTokens(const SourceFile& file, const LexedFile& lexed);

// Stable lower-case names used by the dumps ("identifier", "punctuator", ...).
const char* TokenKindName(TokenKind kind);
const char* TriviaKindName(TriviaKind kind);

// The characters of a punctuator ("<<=" for kShiftLeftEqual); "" for kNone.
std::string_view PunctSpelling(Punct punct);

// `text` with backslash-newline pairs removed: the logical spelling of a token
// that was split over lines (GLSL ES 3.00 allows that).
std::string RemoveLineContinuations(std::string_view text);

// Quotes `text` for a dump: printable ASCII as is, the rest as \n, \r, \t, \xHH.
std::string EscapeForDump(std::string_view text);

}  // namespace shaderport::glsl
