#include "report/fingerprint.h"

#include <cstdint>
#include <cstdio>
#include <map>

#include "diag/rule_renames.h"
#include "report/source_position.h"

namespace shaderport {
namespace {

bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

// FNV-1a: stable across runs and platforms, which std::hash is not.
uint64_t Fnv1a(std::string_view text) {
  uint64_t hash = 14695981039346656037ull;
  for (char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ull;
  }
  return hash;
}

std::string Hex(uint64_t value) {
  char text[24];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

// The nearest line in direction `step` (-1 or +1) from `line` whose text is not
// blank, normalised; "" at either end of the file.
std::string NonBlankNeighbour(const SourceFile& file, uint32_t line, int step) {
  for (int64_t at = int64_t{line} + step; at >= 1 && at <= file.LineCount(); at += step) {
    std::string text = NormalizeWhitespace(file.LineText(static_cast<uint32_t>(at)));
    if (!text.empty()) return text;
  }
  return {};
}

size_t NonSpaceBytes(std::string_view text) {
  size_t count = 0;
  for (char c : text) count += IsSpace(c) ? 0 : 1;
  return count;
}

}  // namespace

std::string NormalizeWhitespace(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  bool pending_space = false;
  for (char c : text) {
    if (IsSpace(c)) {
      pending_space = !out.empty();
      continue;
    }
    if (pending_space) out += ' ';
    pending_space = false;
    out += c;
  }
  return out;
}

std::string FingerprintKey(const SourceManager* sources, const SourceFile* checked_file,
                           const Diagnostic& diagnostic, std::string_view base_directory,
                           bool neighbours) {
  const auto where = Resolve(sources, diagnostic.range);
  const bool located = where && !where->file->IsSynthetic();
  const SourceFile* file = located ? where->file : checked_file;
  // A renamed rule keeps its first id here, so that baselines and SARIF alerts written
  // before the rename still match (diag/rule_renames.def).
  std::string key = std::string(FirstRuleId(diagnostic.rule_id)) + '\n';
  key += (file != nullptr ? DisplayPath(file->Name(), base_directory) : std::string()) + '\n';
  if (!located) return key;
  const uint32_t line = where->start.line;
  const std::string_view text = where->file->LineText(line);
  if (neighbours) key += NonBlankNeighbour(*where->file, line, -1) + '\n';
  key += NormalizeWhitespace(text) + '\n';
  if (neighbours) key += NonBlankNeighbour(*where->file, line, +1) + '\n';
  key += std::to_string(NonSpaceBytes(text.substr(0, where->start.column - 1)));
  return key;
}

std::vector<std::vector<FindingFingerprint>> FingerprintReport(const CheckReport& report,
                                                               std::string_view base_directory) {
  std::map<std::string, int> occurrences;
  std::vector<std::vector<FindingFingerprint>> fingerprints;
  fingerprints.reserve(report.files.size());
  for (const FileReport& file : report.files) {
    std::vector<FindingFingerprint>& of_file = fingerprints.emplace_back();
    of_file.reserve(file.diagnostics.size());
    for (const Diagnostic& diagnostic : file.diagnostics) {
      const std::string key = FingerprintKey(report.sources, file.file, diagnostic, base_directory);
      const std::string line_key =
          FingerprintKey(report.sources, file.file, diagnostic, base_directory, false);
      of_file.push_back(
          {Hex(Fnv1a(key)) + ':' + std::to_string(++occurrences[key]), Hex(Fnv1a(line_key))});
    }
  }
  return fingerprints;
}

}  // namespace shaderport
