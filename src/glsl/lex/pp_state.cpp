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

std::string_view StoreLogicalSpelling(std::string_view text, PpState& state) {
  return state.Store(RemoveLineContinuations(text));
}

SourceRange Cover(SourceRange a, SourceRange b) {
  if (a.file != b.file || b.end < a.begin) return a;
  return {a.file, std::min(a.begin, b.begin), std::max(a.end, b.end)};
}

}  // namespace shaderport::glsl
