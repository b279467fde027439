// How rule goldens (<case>.diag) write findings: position, severity, rule, message,
// then notes and fix-its with their positions.
#pragma once

#include <string>

#include "diag/diagnostic.h"
#include "source/source_file.h"

namespace shaderport::testing {

inline std::string FormatFindings(const std::string& text, const DiagnosticList& diagnostics) {
  const SourceFile file(0, "input", text);
  auto at = [&](uint32_t offset) {
    const LineColumn lc = file.LocationOf(offset);
    return std::to_string(lc.line) + ":" + std::to_string(lc.column);
  };
  std::string out;
  for (const Diagnostic& d : diagnostics) {
    out += at(d.range.begin) + ": " + SeverityName(d.severity) + " [" + d.rule_id + "] " +
           d.message + "\n";
    for (const DiagnosticNote& note : d.notes) {
      out += "  note" + (note.range.Valid() ? " " + at(note.range.begin) : std::string()) + ": " +
             note.message + "\n";
    }
    for (const FixIt& fix : d.fixes) {
      std::string replacement;
      for (char c : fix.replacement) {
        replacement += c == '\n' ? std::string("\\n") : std::string(1, c);
      }
      out += "  fix " + at(fix.range.begin) + "-" + at(fix.range.end) + ": \"" + replacement +
             "\"" + (fix.safety == FixSafety::kSafe ? "" : " (suggestion)") + "\n";
    }
  }
  return out;
}

}  // namespace shaderport::testing
