// The preprocessor's main loop over the lines of each file (not public API).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "glsl/lex/lexer.h"
#include "glsl/lex/pp_state.h"

namespace shaderport::glsl {

// One #if group being read.
struct ConditionalGroup {
  SourceRange directive;  // the opening #if line, for "unterminated" errors
  bool parent_active = true;
  bool taken = false;   // an earlier branch was chosen (or the group is skipped as a whole)
  bool active = false;  // the current branch is being compiled
  bool else_seen = false;
};

class PpDriver {
 public:
  PpDriver(PreprocessResult& result, const PreprocessOptions& options);
  // `lexed`: the file's tokens when the caller has them, else null.
  // first_line: the line the file starts on in one composed text (0: its own line 1).
  void RunFile(const SourceFile& file, size_t index, const LexedFile* lexed, int64_t first_line);
  void Finish(const SourceFile* last_file);

 private:
  // preprocessor.cpp
  bool Active() const { return groups_.empty() || groups_.back().active; }
  // Preprocesses a run of active text tokens (no directive among them) into the result;
  // a run that ends inside a function-like macro's arguments waits for the rest of them
  // (browsers run the directives between: `T(\n#if A\n x\n#else\n y\n#endif\n)`).
  void FlushText(std::span<const Token> text);
  // Expands what waits for the end of a macro call (at the end of a file).
  void FlushPending();
  bool EndsInsideMacroCall(std::span<const Token> text) const;
  std::vector<ExpToken> ToExpTokens(std::span<const Token> tokens);
  void AddLexDiagnostics(const LexedFile& lexed, size_t first_region);
  // Past limits::kMaxCompiledTokens the text is not for glslang: one error at the first
  // token over the limit.
  void ReportOutputTooLarge();

  // directives.cpp: `line` starts with the '#' token.
  void Directive(std::span<const Token> line);
  void Conditional(std::string_view name, std::span<const Token> line, SourceRange range);
  bool Condition(std::string_view name, std::span<const Token> args, SourceRange range);
  void Version(std::span<const Token> args, SourceRange range);
  void Extension(std::span<const Token> args, SourceRange range);
  void Line(std::span<const Token> args, SourceRange range);
  // Runs for every token: the common case (short, or no identifier) stays inline.
  void CheckIdentifierLength(const Token& t) {
    const size_t shortest_limit = max_identifier_length_ != 0 ? max_identifier_length_ : 256;
    if (t.text.size() > shortest_limit &&
        (t.kind == TokenKind::kIdentifier || t.kind == TokenKind::kIntLiteral ||
         t.kind == TokenKind::kUintLiteral || t.kind == TokenKind::kFloatLiteral)) {
      ReportLongIdentifier(t);
    }
  }
  void ReportLongIdentifier(const Token& t);
  SourceRange RangeOf(const Token& t) const { return {file_->Id(), t.begin, t.end}; }

  PpState state_;
  const SourceFile* file_ = nullptr;
  size_t file_index_ = 0;
  bool file_has_backslash_ = true;  // false: no token of file_ holds a line continuation
  std::vector<ConditionalGroup> groups_;
  uint32_t skip_begin_ = 0;  // start of the inactive region being read
  bool seen_token_ = false;  // #version must come before every other token
  bool seen_code_ = false;   // #extension should come before the code
  bool reported_depth_ = false;
  uint32_t max_identifier_length_ = 0;
  std::vector<Token> pending_;  // active text of a macro call that spans directives
};

}  // namespace shaderport::glsl
