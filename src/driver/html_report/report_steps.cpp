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

std::string CascadeOf(const Diagnostic& diagnostic) {
  if (diagnostic.severity != Severity::kError) return "";
  // A compiler keeps going after its first error, and what follows in the same
  // file is mostly that error seen again (an undeclared name, then every use of it).
  const char* compiler = nullptr;
  if (diagnostic.rule_id.starts_with("glslang/")) {
    compiler = "glslang";
  } else if (diagnostic.rule_id == "render/compile-error") {
    compiler = "mesa";
  } else {
    return "";
  }
  return std::string(compiler) + " " + std::to_string(diagnostic.range.file);
}

std::vector<ReportFinding> DiagnosticFindings(const SourceFile* file, DiagnosticList diagnostics,
                                              const SourceManager& sources) {
  CheckReport sorted;
  sorted.sources = &sources;
  FileReport entry;
  entry.file = file;
  entry.diagnostics = std::move(diagnostics);
  sorted.files.push_back(std::move(entry));
  SortReport(sorted);
  ReportOptions options;
  options.summary_line = false;
  std::vector<ReportFinding> findings;
  // One text per finding, so that the page can fold some of them.
  for (Diagnostic& diagnostic : sorted.files.front().diagnostics) {
    ReportFinding finding;
    finding.cascade = CascadeOf(diagnostic);
    CheckReport one;
    one.sources = &sources;
    FileReport only;
    only.file = file;
    only.diagnostics.push_back(std::move(diagnostic));
    one.files.push_back(std::move(only));
    finding.text = FormatText(one, options);
    findings.push_back(std::move(finding));
  }
  return findings;
}

}  // namespace shaderport::driver
