#include "rule/macro_fixes.h"

#include <map>
#include <tuple>

namespace shaderport::rule {
namespace {

// Half-open overlap; an empty range overlaps a range it lies strictly inside of,
// or an empty range at the same offset.
bool Touches(const SourceRange& a, const SourceRange& b) {
  if (a.file != b.file) return false;
  if (a.begin == a.end && b.begin == b.end) return a.begin == b.begin;
  if (a.begin == a.end) return b.begin < a.begin && a.begin < b.end;
  if (b.begin == b.end) return a.begin < b.begin && b.begin < a.end;
  return a.begin < b.end && b.begin < a.end;
}

using EditKey = std::tuple<FileId, uint32_t, uint32_t, std::string>;

EditKey KeyOf(const FixIt& fix) {
  return {fix.range.file, fix.range.begin, fix.range.end, fix.replacement};
}

}  // namespace

MacroPlacement PlacementOf(const glsl::PreprocessResult& preprocessed, const SourceRange& range) {
  if (preprocessed.macro_uses.empty()) return MacroPlacement::kNone;
  bool body = false;
  for (const glsl::MacroUse& use : preprocessed.macro_uses) {
    if (Touches(use.use, range)) return MacroPlacement::kUseSite;
  }
  for (const glsl::PpToken& token : preprocessed.tokens) {
    if (token.macro_use == glsl::kNoMacroUse) continue;
    if (token.in_macro_body && Touches(token.spelling, range)) body = true;
    if (!token.in_macro_body && Touches(token.spelling, range)) return MacroPlacement::kUseSite;
  }
  return body ? MacroPlacement::kBody : MacroPlacement::kNone;
}

std::string MacroNameAt(const glsl::PreprocessResult& preprocessed, const SourceRange& range) {
  for (const glsl::PpToken& token : preprocessed.tokens) {
    if (token.macro_use == glsl::kNoMacroUse) continue;
    if (Touches(token.spelling, range) || Touches(token.expansion, range)) {
      return preprocessed.macro_uses[token.macro_use].name;
    }
  }
  for (const glsl::MacroUse& use : preprocessed.macro_uses) {
    if (Touches(use.use, range)) return use.name;
  }
  return {};
}

size_t MacroFixAgreement::ExpansionCount(const SourceRange& fix_range) const {
  // Each expansion makes one PpToken per body token: count those of the first
  // body token the edit touches.
  const glsl::PpToken* first = nullptr;
  for (const glsl::PpToken& token : preprocessed_.tokens) {
    if (token.in_macro_body && Touches(token.spelling, fix_range)) {
      if (first == nullptr || token.spelling.begin < first->spelling.begin) first = &token;
    }
  }
  if (first == nullptr) return 0;
  size_t count = 0;
  for (const glsl::PpToken& token : preprocessed_.tokens) {
    if (token.in_macro_body && token.spelling == first->spelling) ++count;
  }
  return count;
}

DiagnosticList MacroFixAgreement::Resolve() {
  // Distinct expansions (by use range) that proposed each edit.
  std::map<EditKey, std::vector<SourceRange>> proposers;
  for (const Diagnostic& diagnostic : pending_) {
    for (const FixIt& fix : diagnostic.fixes) {
      auto& ranges = proposers[KeyOf(fix)];
      bool seen = false;
      for (const SourceRange& r : ranges) seen = seen || r == diagnostic.range;
      if (!seen) ranges.push_back(diagnostic.range);
    }
  }
  DiagnosticList resolved;
  for (Diagnostic& diagnostic : pending_) {
    bool agreed = true;
    for (const FixIt& fix : diagnostic.fixes) {
      const size_t expansions = ExpansionCount(fix.range);
      if (expansions == 0 || proposers[KeyOf(fix)].size() < expansions) agreed = false;
      // A different edit to the same bytes from another expansion is a disagreement.
      for (const auto& [key, ranges] : proposers) {
        const SourceRange other{std::get<0>(key), std::get<1>(key), std::get<2>(key)};
        if (key != KeyOf(fix) && (other == fix.range || Touches(other, fix.range))) {
          agreed = false;
        }
      }
    }
    if (!agreed && !diagnostic.fixes.empty()) {
      const std::string name = MacroNameAt(preprocessed_, diagnostic.fixes.front().range);
      diagnostic.fixes.clear();
      diagnostic.notes.push_back(
          {{},
           "not fixed automatically: the fix would edit the body of macro '" + name +
               "', and not every expansion of it needs the same change"});
    }
    resolved.push_back(std::move(diagnostic));
  }
  pending_.clear();
  return resolved;
}

}  // namespace shaderport::rule
