#include "report/check_report.h"

#include <algorithm>
#include <set>
#include <string_view>
#include <tuple>

namespace shaderport {

ReportSummary Summarize(const CheckReport& report) {
  ReportSummary summary;
  std::set<std::string_view> projects;
  for (const FileReport& file : report.files) {
    if (file.role != FileRole::kInput) ++summary.files_checked;
    if (file.role == FileRole::kTab) {
      ++summary.tabs_checked;
      projects.insert(file.project);
    }
    if (!file.diagnostics.empty()) ++summary.files_with_problems;
    for (const Diagnostic& diagnostic : file.diagnostics) {
      if (IsFixable(diagnostic)) ++summary.fixable;
      switch (diagnostic.severity) {
        case Severity::kError:
          ++summary.errors;
          break;
        case Severity::kWarning:
          ++summary.warnings;
          break;
        case Severity::kNote:
          ++summary.notes;
          break;
      }
    }
  }
  summary.projects = projects.size();
  return summary;
}

bool ReportFails(const CheckReport& report) {
  for (const FileReport& file : report.files) {
    for (const Diagnostic& diagnostic : file.diagnostics) {
      if (diagnostic.severity >= file.fail_on) return true;
    }
  }
  return false;
}

void SortReport(CheckReport& report) {
  std::stable_sort(report.files.begin(), report.files.end(),
                   [](const FileReport& a, const FileReport& b) {
                     if (!a.file || !b.file) return b.file != nullptr && a.file == nullptr;
                     return a.file->Name() < b.file->Name();
                   });
  for (FileReport& file : report.files) {
    // Diagnostics without a location describe the whole file: they come first.
    std::stable_sort(
        file.diagnostics.begin(), file.diagnostics.end(),
        [](const Diagnostic& a, const Diagnostic& b) {
          const bool valid_a = a.range.Valid();
          const bool valid_b = b.range.Valid();
          return std::tie(valid_a, a.range.file, a.range.begin, a.range.end, a.rule_id) <
                 std::tie(valid_b, b.range.file, b.range.begin, b.range.end, b.rule_id);
        });
  }
}

}  // namespace shaderport
