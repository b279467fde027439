#include "rule/fix_selection.h"

#include <string>

namespace shaderport::rule {
namespace {

struct Accepted {
  Edit edit;
  size_t owner;  // diagnostic index
};

}  // namespace

FixSelection SelectFixes(DiagnosticList& diagnostics, const FixSelectionOptions& options) {
  FixSelection selection;
  std::vector<Accepted> accepted;
  for (size_t i = 0; i < diagnostics.size(); ++i) {
    Diagnostic& diagnostic = diagnostics[i];
    std::vector<Edit> group;
    bool usable = !diagnostic.fixes.empty();
    for (const FixIt& fix : diagnostic.fixes) {
      if (fix.safety != FixSafety::kSafe && !options.apply_suggestions) usable = false;
      if (fix.range.file != options.file || fix.range.begin > fix.range.end) usable = false;
      group.push_back({fix.range.begin, fix.range.end, fix.replacement});
    }
    if (!usable) continue;
    if (options.allow && !options.allow(diagnostic)) {
      if (!options.refused_note.empty()) diagnostic.notes.push_back({{}, options.refused_note});
      continue;
    }
    // Within one diagnostic the edits must agree with each other too.
    const Diagnostic* winner = nullptr;
    bool conflict = false;
    for (size_t a = 0; a < group.size() && !conflict; ++a) {
      for (size_t b = a + 1; b < group.size(); ++b) {
        if (group[a] != group[b] && EditsOverlap(group[a], group[b])) conflict = true;
      }
    }
    std::vector<bool> duplicate(group.size(), false);
    for (size_t g = 0; g < group.size() && !conflict; ++g) {
      for (const Accepted& other : accepted) {
        if (other.edit == group[g]) {
          duplicate[g] = true;  // two findings asking for the same edit
        } else if (EditsOverlap(other.edit, group[g])) {
          conflict = true;
          winner = &diagnostics[other.owner];
          break;
        }
      }
    }
    if (conflict) {
      diagnostic.notes.push_back({{},
                                  winner != nullptr
                                      ? "not applied in this round: overlaps the fix of '" +
                                            winner->rule_id + "', which goes first"
                                      : std::string("not applied: its edits overlap each other")});
      continue;
    }
    for (size_t g = 0; g < group.size(); ++g) {
      bool again = duplicate[g];
      for (size_t h = 0; h < g && !again; ++h) again = group[h] == group[g];
      if (again) continue;
      accepted.push_back({group[g], i});
      selection.edits.push_back(std::move(group[g]));
    }
    selection.applied.push_back(i);
  }
  return selection;
}

}  // namespace shaderport::rule
