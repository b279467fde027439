#include "driver/port/port_report.h"

#include <algorithm>

#include "report/text_format.h"

namespace shaderport::driver {

bool HasFindings(std::span<const PortResult> results) {
  for (const PortResult& result : results) {
    for (const Diagnostic& d : result.diagnostics) {
      if (d.severity != Severity::kNote) return true;
    }
  }
  return false;
}

bool AllConverged(std::span<const PortResult> results) {
  return std::all_of(results.begin(), results.end(),
                     [](const PortResult& result) { return result.converged; });
}

bool FailsAt(std::span<const PortResult> results, Severity fail_on) {
  for (const PortResult& result : results) {
    for (const Diagnostic& d : result.diagnostics) {
      if (d.severity >= fail_on) return true;
    }
  }
  return false;
}

std::string FormatPortFindings(std::span<const PortResult> results, const SourceManager& sources,
                               bool color) {
  CheckReport report;
  report.sources = &sources;
  for (const PortResult& result : results) {
    FileReport file;
    file.file = result.file;
    file.stage = std::string(StageName(result.kind.stage));
    file.dialect = std::string(DialectName(result.kind.dialect));
    file.diagnostics = result.diagnostics;
    report.files.push_back(std::move(file));
  }
  SortReport(report);
  ReportOptions options;
  options.color = color;
  return FormatText(report, options);
}

}  // namespace shaderport::driver
