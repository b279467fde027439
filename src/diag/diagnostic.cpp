#include "diag/diagnostic.h"

namespace shaderport {

const char* SeverityName(Severity severity) {
  switch (severity) {
    case Severity::kNote:
      return "note";
    case Severity::kWarning:
      return "warning";
    case Severity::kError:
      return "error";
  }
  return "error";
}

std::optional<Severity> SeverityFromName(std::string_view name) {
  for (const Severity severity : {Severity::kNote, Severity::kWarning, Severity::kError}) {
    if (name == SeverityName(severity)) return severity;
  }
  return std::nullopt;
}

Diagnostic MakeDiagnostic(Severity severity, std::string rule_id, SourceRange range,
                          std::string message) {
  Diagnostic diagnostic;
  diagnostic.severity = severity;
  diagnostic.rule_id = std::move(rule_id);
  diagnostic.range = range;
  diagnostic.message = std::move(message);
  return diagnostic;
}

}  // namespace shaderport
