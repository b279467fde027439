#include "report/baseline.h"

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <tuple>

#include "report/fingerprint.h"
#include "report/source_position.h"

namespace shaderport {
namespace {

using Json = nlohmann::ordered_json;

void SortEntries(std::vector<BaselineEntry>& entries) {
  std::sort(entries.begin(), entries.end(), [](const BaselineEntry& a, const BaselineEntry& b) {
    return std::tie(a.path, a.rule, a.message, a.fingerprint) <
           std::tie(b.path, b.rule, b.message, b.fingerprint);
  });
}

// The file the finding is shown in, as the formats show it (relative to the base).
std::string ShownPath(const CheckReport& report, const FileReport& file,
                      const Diagnostic& diagnostic, std::string_view base_directory) {
  const auto where = Resolve(report.sources, diagnostic.range);
  const SourceFile* shown = where && !where->file->IsSynthetic() ? where->file : file.file;
  return shown != nullptr ? DisplayPath(shown->Name(), base_directory) : std::string();
}

// An optional string member; false when present but not a string.
bool ReadString(const Json& object, const char* key, std::string& out) {
  const auto it = object.find(key);
  if (it == object.end()) return true;
  if (!it->is_string()) return false;
  out = it->get<std::string>();
  return true;
}

}  // namespace

Baseline BaselineOfReport(const CheckReport& report, std::string_view base_directory) {
  const auto fingerprints = FingerprintReport(report, base_directory);
  Baseline baseline;
  for (size_t f = 0; f < report.files.size(); ++f) {
    const FileReport& file = report.files[f];
    for (size_t d = 0; d < file.diagnostics.size(); ++d) {
      const Diagnostic& diagnostic = file.diagnostics[d];
      baseline.entries.push_back(
          {fingerprints[f][d].fingerprint, fingerprints[f][d].line_fingerprint, diagnostic.rule_id,
           ShownPath(report, file, diagnostic, base_directory), diagnostic.message});
    }
  }
  SortEntries(baseline.entries);
  return baseline;
}

std::string FormatBaseline(const Baseline& baseline) {
  std::vector<BaselineEntry> entries = baseline.entries;
  SortEntries(entries);
  Json findings = Json::array();
  for (const BaselineEntry& entry : entries) {
    findings.push_back({{"fingerprint", entry.fingerprint},
                        {"lineFingerprint", entry.line_fingerprint},
                        {"rule", entry.rule},
                        {"path", entry.path},
                        {"message", entry.message}});
  }
  const Json document = {{"version", kBaselineVersion}, {"findings", std::move(findings)}};
  return document.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::optional<Baseline> ParseBaseline(std::string_view text, std::string& error) {
  const Json document = Json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (document.is_discarded()) {
    error = "not valid JSON";
    return std::nullopt;
  }
  if (!document.is_object()) {
    error = "expected a JSON object with 'version' and 'findings'";
    return std::nullopt;
  }
  const auto version = document.find("version");
  if (version == document.end() || !version->is_number_integer()) {
    error = "no integer 'version'";
    return std::nullopt;
  }
  if (*version != kBaselineVersion) {
    error = "version " + version->dump() + " is not supported (this build reads version " +
            std::to_string(kBaselineVersion) + ")";
    return std::nullopt;
  }
  const auto findings = document.find("findings");
  if (findings == document.end() || !findings->is_array()) {
    error = "no 'findings' array";
    return std::nullopt;
  }
  Baseline baseline;
  for (size_t i = 0; i < findings->size(); ++i) {
    const Json& item = (*findings)[i];
    BaselineEntry entry;
    const bool ok = item.is_object() && ReadString(item, "fingerprint", entry.fingerprint) &&
                    ReadString(item, "lineFingerprint", entry.line_fingerprint) &&
                    ReadString(item, "rule", entry.rule) && ReadString(item, "path", entry.path) &&
                    ReadString(item, "message", entry.message);
    if (!ok || entry.fingerprint.empty()) {
      error = "findings[" + std::to_string(i) +
              "] is not an object with a string 'fingerprint' (and string 'lineFingerprint', "
              "'rule', 'path', 'message')";
      return std::nullopt;
    }
    baseline.entries.push_back(std::move(entry));
  }
  return baseline;
}

BaselineOutcome ApplyBaseline(CheckReport& report, const Baseline& baseline,
                              std::string_view base_directory) {
  // Entries not matched yet, by fingerprint and by line fingerprint (in file order).
  std::multimap<std::string, size_t, std::less<>> by_fingerprint;
  std::multimap<std::string, size_t, std::less<>> by_line;
  for (size_t i = 0; i < baseline.entries.size(); ++i) {
    by_fingerprint.emplace(baseline.entries[i].fingerprint, i);
    if (!baseline.entries[i].line_fingerprint.empty()) {
      by_line.emplace(baseline.entries[i].line_fingerprint, i);
    }
  }
  std::vector<bool> entry_used(baseline.entries.size(), false);
  auto take = [&](std::multimap<std::string, size_t, std::less<>>& index, const std::string& key) {
    for (auto [it, end] = index.equal_range(key); it != end; ++it) {
      if (!entry_used[it->second]) {
        entry_used[it->second] = true;
        return true;
      }
    }
    return false;
  };
  const auto fingerprints = FingerprintReport(report, base_directory);
  std::vector<std::vector<bool>> baselined(report.files.size());
  for (size_t f = 0; f < report.files.size(); ++f) {
    for (const FindingFingerprint& finding : fingerprints[f]) {
      baselined[f].push_back(take(by_fingerprint, finding.fingerprint));
    }
  }
  for (size_t f = 0; f < report.files.size(); ++f) {
    for (size_t d = 0; d < fingerprints[f].size(); ++d) {
      if (!baselined[f][d]) baselined[f][d] = take(by_line, fingerprints[f][d].line_fingerprint);
    }
  }
  BaselineOutcome outcome;
  for (size_t f = 0; f < report.files.size(); ++f) {
    DiagnosticList kept;
    DiagnosticList& diagnostics = report.files[f].diagnostics;
    for (size_t d = 0; d < diagnostics.size(); ++d) {
      if (baselined[f][d]) {
        ++outcome.baselined;
      } else {
        kept.push_back(std::move(diagnostics[d]));
      }
    }
    diagnostics = std::move(kept);
  }
  for (size_t i = 0; i < baseline.entries.size(); ++i) {
    if (!entry_used[i]) outcome.fixed.push_back(baseline.entries[i]);
  }
  SortEntries(outcome.fixed);
  return outcome;
}

std::string FormatBaselineSummary(const BaselineOutcome& outcome) {
  auto count = [](size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
  };
  std::string text = count(outcome.baselined, "finding", "findings") + " in the baseline " +
                     (outcome.baselined == 1 ? "was" : "were") + " not reported";
  if (!outcome.fixed.empty()) {
    text += "; " + count(outcome.fixed.size(), "baseline entry is", "baseline entries are") +
            " fixed; rewrite the baseline with --write-baseline";
  }
  return text + "\n";
}

}  // namespace shaderport
