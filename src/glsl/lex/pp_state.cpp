#include "glsl/lex/pp_state.h"

#include <algorithm>

#include "base/limits.h"
#include "glsl/lex/lexer.h"

namespace shaderport::glsl {

void PpState::Report(Severity severity, std::string_view rule, SourceRange range,
                     std::string message) {
  auto& list = result.diagnostics;
  if (list.size() >= limits::kMaxDiagnosticsPerFile) {
    if (list.back().notes.empty()) {
      list.back().notes.push_back({{}, "further preprocessor diagnostics were dropped"});
    }
    return;
  }
  Diagnostic d;
  d.severity = severity;
  d.rule_id = std::string(rule);
  d.range = range;
  d.message = std::move(message);
  list.push_back(std::move(d));
}

PpToken ToPpToken(const SourceFile& file, const Token& token, PpState& state,
                  bool file_has_backslash) {
  PpToken t;
  t.kind = token.kind;
  t.punct = token.punct;
  t.text = token.text;
  // The parser wants the logical spelling: drop backslash-newlines inside the token.
  if (file_has_backslash && token.text.find('\\') != std::string_view::npos &&
      token.kind != TokenKind::kInvalid) {
    t.text = state.Store(RemoveLineContinuations(token.text));
  }
  t.spelling = {file.Id(), token.begin, token.end};
  t.expansion = t.spelling;
  t.leading_space = token.leading_space;
  t.at_line_start = token.at_line_start;
  return t;
}

SourceRange Cover(SourceRange a, SourceRange b) {
  if (a.file != b.file || b.end < a.begin) return a;
  return {a.file, std::min(a.begin, b.begin), std::max(a.end, b.end)};
}

}  // namespace shaderport::glsl
