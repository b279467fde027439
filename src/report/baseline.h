// The baseline ratchet of `check --baseline`: a file of the findings a project
// has accepted, so that only new findings are reported and fail the run.
// Findings are matched by fingerprint (report/fingerprint.h), never by line.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "report/check_report.h"

namespace shaderport {

// The version of the baseline file format (docs/output-formats.md).
inline constexpr int kBaselineVersion = 1;

struct BaselineEntry {
  std::string fingerprint;       // what is matched (report/fingerprint.h)
  std::string line_fingerprint;  // the second chance when a neighbouring line changed
  std::string rule;              // rule, path and message only help people read the file
  std::string path;
  std::string message;
  friend bool operator==(const BaselineEntry&, const BaselineEntry&) = default;
};

// Sorted by path, rule, fingerprint: the file diffs well when findings change.
struct Baseline {
  std::vector<BaselineEntry> entries;
};

// One entry per diagnostic of `report`, with paths and fingerprints relative
// to `base_directory`.
Baseline BaselineOfReport(const CheckReport& report, std::string_view base_directory);

// The JSON text of the baseline file: sorted, two-space indented, one key per line.
std::string FormatBaseline(const Baseline& baseline);

// nullopt with `error` set when `text` is not a baseline file of a version this
// build reads (not JSON, wrong version, an entry without a fingerprint, ...).
std::optional<Baseline> ParseBaseline(std::string_view text, std::string& error);

struct BaselineOutcome {
  size_t baselined = 0;              // findings left out because the baseline holds them
  std::vector<BaselineEntry> fixed;  // entries that match no finding: removable
};

// Drops from `report` every diagnostic that an entry of `baseline` matches, each
// entry matching at most one finding: first by fingerprint, then, for the
// findings left, by line fingerprint (the finding's line is unchanged but a
// neighbouring line was edited, perhaps to fix a finding there).
BaselineOutcome ApplyBaseline(CheckReport& report, const Baseline& baseline,
                              std::string_view base_directory);

// The summary line of a run with a baseline: how many findings it held back and,
// when entries no longer match, that the baseline can be rewritten; ends in '\n'.
std::string FormatBaselineSummary(const BaselineOutcome& outcome);

}  // namespace shaderport
