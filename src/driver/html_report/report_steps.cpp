#include "driver/html_report/report_steps.h"

#include "report/check_report.h"
#include "report/text_format.h"

namespace shaderport::driver {

StepStatus StatusOf(const DiagnosticList& diagnostics) {
  StepStatus status = StepStatus::kPass;
  for (const Diagnostic& d : diagnostics) {
    if (d.severity == Severity::kError) return StepStatus::kFail;
    if (d.severity == Severity::kWarning) status = StepStatus::kWarn;
  }
  return status;
}

std::string DiagnosticText(const SourceFile* file, DiagnosticList diagnostics,
                           const SourceManager& sources) {
  if (diagnostics.empty()) return "";
  CheckReport report;
  report.sources = &sources;
  FileReport entry;
  entry.file = file;
  entry.diagnostics = std::move(diagnostics);
  report.files.push_back(std::move(entry));
  SortReport(report);
  std::string text = FormatText(report, ReportOptions{});
  // FormatText ends with a summary line; drop it.
  while (!text.empty() && text.back() == '\n') text.pop_back();
  const size_t last = text.rfind('\n');
  text.resize(last == std::string::npos ? 0 : last + 1);
  return text;
}

}  // namespace shaderport::driver
