#include "rule/rule_context.h"

#include "base/limits.h"

namespace shaderport::rule {

std::string_view RuleContext::TextOf(const SourceRange& range) const {
  const std::string_view text = file_.Text();
  if (range.file != file_.Id() || range.begin > range.end || range.end > text.size()) return {};
  return text.substr(range.begin, range.end - range.begin);
}

bool RuleContext::InMacro(const SourceRange& range) const {
  return PlacementOf(preprocessed_, range) != MacroPlacement::kNone;
}

void RuleContext::Report(Diagnostic diagnostic, bool allow_in_macro) {
  if (diagnostics_.size() >= limits::kMaxDiagnosticsPerFile) {
    if (!over_limit_ && !diagnostics_.empty()) {
      diagnostics_.back().notes.push_back(
          {{}, "further findings of this rule were dropped (too many in one file)"});
    }
    over_limit_ = true;
    return;
  }
  if (allow_in_macro || diagnostic.fixes.empty()) {
    diagnostics_.push_back(std::move(diagnostic));
    return;
  }
  MacroPlacement worst = MacroPlacement::kNone;
  SourceRange where;
  for (const FixIt& fix : diagnostic.fixes) {
    const MacroPlacement placement = PlacementOf(preprocessed_, fix.range);
    if (placement == MacroPlacement::kUseSite ||
        (placement == MacroPlacement::kBody && worst == MacroPlacement::kNone)) {
      worst = placement;
      where = fix.range;
    }
  }
  if (worst == MacroPlacement::kBody) {
    macro_fixes_.Propose(std::move(diagnostic));
    return;
  }
  if (worst == MacroPlacement::kUseSite) {
    diagnostic.fixes.clear();
    diagnostic.notes.push_back({where, "not fixed automatically: inside macro '" +
                                           MacroNameAt(preprocessed_, where) + "'"});
  }
  diagnostics_.push_back(std::move(diagnostic));
}

DiagnosticList RuleContext::TakeDiagnostics() {
  if (!macro_fixes_.Empty()) {
    for (Diagnostic& diagnostic : macro_fixes_.Resolve()) {
      diagnostics_.push_back(std::move(diagnostic));
    }
  }
  return std::move(diagnostics_);
}

}  // namespace shaderport::rule
