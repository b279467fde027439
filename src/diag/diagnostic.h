// The one diagnostic model every stage reports into.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "source/source_file.h"

namespace shaderport {

enum class Severity : uint8_t { kNote, kWarning, kError };

// How far a fix can be trusted: `port` applies only safe fixes; suggestions are shown.
enum class FixSafety : uint8_t { kSafe, kSuggestion };

// Replace `range` with `replacement`. An empty range inserts; an empty replacement deletes.
struct FixIt {
  SourceRange range;
  std::string replacement;
  FixSafety safety = FixSafety::kSafe;
};

// A secondary location that helps explain the primary one.
struct DiagnosticNote {
  SourceRange range;  // may be invalid for a note with no location
  std::string message;
};

struct Diagnostic {
  Severity severity = Severity::kError;
  std::string rule_id;  // "category/kebab-name", see docs/diagnostics.md
  SourceRange range;    // into an original or synthetic file, never generated output
  std::string message;
  std::vector<DiagnosticNote> notes;
  std::vector<FixIt> fixes;
};

using DiagnosticList = std::vector<Diagnostic>;

inline bool HasErrors(const DiagnosticList& diagnostics) {
  for (const auto& d : diagnostics) {
    if (d.severity == Severity::kError) return true;
  }
  return false;
}

// A finding `shaderport fix` repairs: it carries a safe fix-it (check attaches the
// fixes of the rules that repair glslang's errors, driver/fixable_findings.h).
inline bool IsFixable(const Diagnostic& diagnostic) {
  for (const auto& fix : diagnostic.fixes) {
    if (fix.safety == FixSafety::kSafe) return true;
  }
  return false;
}

const char* SeverityName(Severity severity);
// The inverse of SeverityName ("note", "warning", "error"); nothing for other text.
std::optional<Severity> SeverityFromName(std::string_view name);

// A diagnostic with no notes or fixes yet.
Diagnostic MakeDiagnostic(Severity severity, std::string rule_id, SourceRange range,
                          std::string message);

}  // namespace shaderport
