#include "driver/suppress/suppressions.h"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "driver/config/rule_pattern.h"
#include "driver/suppress/suppression_comment.h"

namespace shaderport::driver {
namespace {

struct ActiveSuppression {
  SourceRange comment;
  uint32_t line = 0;  // the line it covers
  std::vector<SourceRange> pattern_ranges;
  std::vector<std::string> patterns;  // empty: every rule
  std::vector<bool> used;             // per pattern, or one flag for "every rule"
};

bool IsComment(glsl::TriviaKind kind) {
  return kind == glsl::TriviaKind::kLineComment || kind == glsl::TriviaKind::kBlockComment;
}

bool InsideAny(std::span<const SourceRange> regions, const SourceRange& range) {
  return std::any_of(regions.begin(), regions.end(),
                     [&](const SourceRange& region) { return region.Contains(range); });
}

Diagnostic Warning(std::string rule, SourceRange range, std::string message) {
  Diagnostic d;
  d.severity = Severity::kWarning;
  d.rule_id = std::move(rule);
  d.range = range;
  d.message = std::move(message);
  return d;
}

class Suppressor {
 public:
  Suppressor(const SourceFile& file, DiagnosticList& diagnostics)
      : file_(file), diagnostics_(diagnostics) {}

  void Collect(const glsl::LexedFile& lexed, std::span<const SourceRange> inactive_regions) {
    for (const glsl::Trivia& trivia : lexed.trivia) {
      if (!IsComment(trivia.kind)) continue;
      const SourceRange range{file_.Id(), trivia.begin, trivia.end};
      if (InsideAny(inactive_regions, range)) continue;
      AddComment(range);
    }
  }

  void Apply(const SuppressionOptions& options) {
    std::multimap<uint32_t, size_t> by_line;
    for (size_t i = 0; i < suppressions_.size(); ++i) by_line.emplace(suppressions_[i].line, i);
    std::erase_if(diagnostics_, [&](const Diagnostic& d) {
      if (d.range.file != file_.Id() || d.rule_id.starts_with("suppression/")) return false;
      const uint32_t line = file_.LocationOf(d.range.begin).line;
      bool silenced = false;
      for (auto [it, last] = by_line.equal_range(line); it != last; ++it) {
        silenced |= Match(suppressions_[it->second], d.rule_id);
      }
      return silenced;
    });
    for (Diagnostic& d : new_diagnostics_) diagnostics_.push_back(std::move(d));
    if (options.report_unused) ReportUnused();
  }

 private:
  // Marks every pattern that matches: each one then counts as used.
  static bool Match(ActiveSuppression& suppression, const std::string& rule_id) {
    if (suppression.patterns.empty()) return suppression.used[0] = true;
    bool matched = false;
    for (size_t i = 0; i < suppression.patterns.size(); ++i) {
      if (RulePatternMatches(suppression.patterns[i], rule_id)) {
        suppression.used[i] = true;
        matched = true;
      }
    }
    return matched;
  }

  void AddComment(const SourceRange& range) {
    const std::string_view text = file_.Text().substr(range.begin, range.Size());
    // A comment continued with backslash-newline is read as one logical line.
    const bool continued =
        text.find('\\') != std::string_view::npos && glsl::RemoveLineContinuations(text) != text;
    const std::string logical = continued ? glsl::RemoveLineContinuations(text) : std::string(text);
    const std::optional<SuppressionDirective> directive = ParseSuppressionComment(logical);
    if (!directive) return;
    if (!directive->error.empty()) {
      new_diagnostics_.push_back(Warning("suppression/malformed", range,
                                         "malformed suppression comment: " + directive->error));
      return;
    }
    ActiveSuppression suppression;
    suppression.comment = range;
    suppression.line = directive->next_line ? file_.LocationOf(range.end).line + 1
                                            : file_.LocationOf(range.begin).line;
    for (const RulePatternSpan& span : directive->patterns) {
      SourceRange pattern_range = range;
      if (!continued) {
        pattern_range.begin = range.begin + span.offset;
        pattern_range.end = pattern_range.begin + static_cast<uint32_t>(span.pattern.size());
      }
      if (!RulePatternMatchesCatalog(span.pattern)) {
        new_diagnostics_.push_back(
            Warning("suppression/unknown-rule", pattern_range,
                    "'" + span.pattern + "' matches no rule shaderport knows"));
        continue;  // it can never be used: reported once, not again as unused
      }
      suppression.patterns.push_back(span.pattern);
      suppression.pattern_ranges.push_back(pattern_range);
    }
    if (!directive->patterns.empty() && suppression.patterns.empty()) return;
    suppression.used.assign(std::max<size_t>(suppression.patterns.size(), 1), false);
    suppressions_.push_back(std::move(suppression));
  }

  void ReportUnused() {
    for (const ActiveSuppression& s : suppressions_) {
      const std::string where = " silenced nothing on line " + std::to_string(s.line);
      const bool none_used = std::none_of(s.used.begin(), s.used.end(), [](bool b) { return b; });
      if (s.patterns.empty()) {
        if (none_used) Report(s, s.comment, "suppression comment" + where, true);
        continue;
      }
      for (size_t i = 0; i < s.patterns.size(); ++i) {
        if (s.used[i]) continue;
        // When nothing in the comment was used, the first warning offers to delete it.
        Report(s, s.pattern_ranges[i], "suppression of '" + s.patterns[i] + "'" + where,
               none_used && i == 0);
      }
    }
  }

  void Report(const ActiveSuppression& s, SourceRange range, std::string message,
              bool offer_removal) {
    Diagnostic d = Warning("suppression/unused", range, std::move(message));
    if (offer_removal) d.fixes.push_back({s.comment, "", FixSafety::kSuggestion});
    diagnostics_.push_back(std::move(d));
  }

  const SourceFile& file_;
  DiagnosticList& diagnostics_;
  std::vector<ActiveSuppression> suppressions_;
  DiagnosticList new_diagnostics_;
};

}  // namespace

void ApplySuppressions(const SourceFile& file, const glsl::LexedFile& lexed,
                       DiagnosticList& diagnostics, std::span<const SourceRange> inactive_regions,
                       const SuppressionOptions& options) {
  Suppressor suppressor(file, diagnostics);
  suppressor.Collect(lexed, inactive_regions);
  suppressor.Apply(options);
}

}  // namespace shaderport::driver
