// The GLSL ES preprocessor: turns the lexed files of one shader into the token
// stream the parser reads, remembering where every token came from.
#pragma once

#include <cstdint>
#include <deque>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "glsl/lex/token.h"
#include "source/source_file.h"
#include "source/source_manager.h"

namespace shaderport::glsl {

struct LexedFile;  // glsl/lex/lexer.h

inline constexpr uint32_t kNoMacroUse = UINT32_MAX;

// A token after preprocessing.
struct PpToken {
  TokenKind kind = TokenKind::kEndOfFile;
  Punct punct = Punct::kNone;
  std::string_view text;  // spelling; points into a SourceFile or into PreprocessResult storage
  SourceRange spelling;   // where its characters are written (inside a macro body for expanded
                          // tokens; the whole `a ## b` for pasted ones)
  SourceRange expansion;  // what it stands for in the file being compiled: its own spelling
                          // when not from a macro, else the range of the outermost macro use
  uint32_t macro_use = kNoMacroUse;  // innermost MacroUse that produced it, if any
  bool leading_space = false;
  bool at_line_start = false;
  // Spelled inside a #define body (or built by `##` or a built-in macro such as __LINE__):
  // an edit to `spelling` would change the macro, not just this use. Tokens of macro
  // arguments keep false: they are written at the use.
  bool in_macro_body = false;
};

// One expansion of a macro; uses nest through `parent`.
struct MacroUse {
  std::string name;
  SourceRange use;         // the macro name and, for function-like macros, its arguments
  SourceRange definition;  // the #define line's macro name
  uint32_t parent = kNoMacroUse;
};

struct VersionDirective {
  bool present = false;
  int number = 100;     // 100 when absent (GLSL ES 1.00)
  std::string profile;  // "es" or ""
  SourceRange range;
};

struct ExtensionDirective {
  std::string name;
  std::string behavior;
  SourceRange range;
};

struct PragmaDirective {
  std::string text;   // the tokens after `#pragma`, joined by single spaces
  SourceRange range;  // the whole directive line
};

struct PreprocessOptions {
  // Macros defined before the first file, as "NAME" or "NAME=value" (e.g. GL_ES).
  std::vector<std::string> predefined;
  // Longest identifier accepted; 0 picks WebGL's limit from the #version: 256 for GLSL ES 1.00,
  // 1024 for 3.00. WebGL 2 contexts allow 1024 for ES 1.00 shaders too: pass 1024 there.
  uint32_t max_identifier_length = 0;
  // Tokens of `files` the caller lexed already, by position (missing or null:
  // lexed here). They must be Lex() of the same file and outlive the call.
  std::vector<const LexedFile*> lexed;
  // The line each file starts on when the files are parts of one text behind lines
  // of their own (ShaderToy: header, Common, pass), for __LINE__; __FILE__ is then 0
  // throughout. Empty: each file is a source string of its own from line 1.
  std::vector<int64_t> first_lines;
};

struct PreprocessResult {
  std::vector<PpToken> tokens;  // ends with one kEndOfFile token
  std::vector<MacroUse> macro_uses;
  VersionDirective version;
  std::vector<ExtensionDirective> extensions;
  std::vector<PragmaDirective> pragmas;
  std::vector<SourceRange> inactive_regions;  // skipped #if groups (kept as trivia)
  // Text of tokens made by `##`: a deque so that views into it survive moves.
  std::deque<std::string> storage;
  DiagnosticList diagnostics;
};

// Preprocesses `files` in order as one translation unit (e.g. ShaderToy Common
// followed by a pass): macros defined in one file stay defined in the next.
PreprocessResult Preprocess(std::span<const SourceFile* const> files,
                            const PreprocessOptions& options = {});

// One line per token, "file:line:col kind 'text'" at the token's expansion, followed by
// " <- spelled file:line:col via MACRO < OUTER" for tokens that come from macros.
// For `shaderport dump --pp-tokens` and golden tests.
std::string DumpPpTokens(const PreprocessResult& result, const SourceManager& sources);

}  // namespace shaderport::glsl
