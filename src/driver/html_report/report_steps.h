// What the report's steps share: a status from findings, and findings as clang-style text.
#pragma once

#include <vector>

#include "diag/diagnostic.h"
#include "driver/html_report/html_report.h"
#include "source/source_manager.h"

namespace shaderport::driver {

StepStatus StatusOf(const DiagnosticList& diagnostics);

// `diagnostics` in position order, each as its own clang-style text (no summary
// line: the badges say it), compiler errors keyed by their cascade (CascadeOf).
std::vector<ReportFinding> DiagnosticFindings(const SourceFile* file, DiagnosticList diagnostics,
                                              const SourceManager& sources);

// The cascade key of a compiler error: "glslang <file>" for a glslang/* error,
// "mesa <file>" for render/compile-error, where <file> is the id of the file the
// error points into; "" for everything else (shaderport's own rules stand alone).
std::string CascadeOf(const Diagnostic& diagnostic);

}  // namespace shaderport::driver
