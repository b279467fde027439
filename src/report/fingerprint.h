// A finding's identity across edits, for SARIF's partialFingerprints and the
// baseline: the rule, the file's path relative to the base directory and the
// text of the flagged line and its neighbours, never the line number, so that
// a finding keeps its fingerprint when unrelated lines are added or removed
// above it, when the file is re-indented, or when the tree is checked out
// somewhere else.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "report/check_report.h"

namespace shaderport {

// The partialFingerprints key; bumped whenever what is hashed changes.
inline constexpr const char* kFingerprintKey = "shaderport/v2";

// Every run of whitespace becomes one space; leading and trailing whitespace goes.
std::string NormalizeWhitespace(std::string_view text);

// What a fingerprint hashes, one field per line: rule id, path, the previous
// and next non-blank lines and the flagged line (whitespace normalised), and
// where in the flagged line the range starts, counted in non-whitespace bytes so
// that re-indenting does not move it. A finding in a synthetic file (generated
// code) or without a location is keyed on `checked_file` alone, as SARIF shows it.
// Without `neighbours`, the two neighbouring lines are left out.
std::string FingerprintKey(const SourceManager* sources, const SourceFile* checked_file,
                           const Diagnostic& diagnostic, std::string_view base_directory,
                           bool neighbours = true);

struct FindingFingerprint {
  // 16 hex digits of the key's 64-bit FNV-1a hash, ':', and the 1-based
  // occurrence of that key in the report, so that identical findings (the same
  // code repeated in one file) stay distinct.
  std::string fingerprint;
  // The hash of the key without neighbours (16 hex digits): a second chance to
  // recognise a finding whose neighbouring line was edited (or fixed).
  std::string line_fingerprint;
};

// The fingerprints of every diagnostic of `report`, in report order (one
// vector per file).
std::vector<std::vector<FindingFingerprint>> FingerprintReport(const CheckReport& report,
                                                               std::string_view base_directory);

}  // namespace shaderport
