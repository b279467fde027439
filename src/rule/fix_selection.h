// Choosing which fix-its of one round to apply: whole diagnostics at a time
// (all of a diagnostic's fixes or none), earlier diagnostics first, never two
// overlapping edits. Losers keep their diagnostic and get a note.
#pragma once

#include <functional>
#include <vector>

#include "diag/diagnostic.h"
#include "source/edit.h"

namespace shaderport::rule {

struct FixSelection {
  std::vector<Edit> edits;      // non-overlapping, duplicates removed
  std::vector<size_t> applied;  // indices of diagnostics whose fixes are all in `edits`
};

struct FixSelectionOptions {
  FileId file = kNoFile;           // only edits to this file can be applied
  bool apply_suggestions = false;  // kSuggestion fixes too (else only kSafe)
  // When set and false for a diagnostic, its fixes are skipped with `refused_note`.
  std::function<bool(const Diagnostic&)> allow;
  std::string refused_note;
};

// `diagnostics` must be in priority order (registry order of their rules). Adds
// notes to diagnostics whose fixes were not applied.
FixSelection SelectFixes(DiagnosticList& diagnostics, const FixSelectionOptions& options);

}  // namespace shaderport::rule
