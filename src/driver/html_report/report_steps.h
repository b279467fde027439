// What the report's steps share: a status from findings, and findings as clang-style text.
#pragma once

#include <string>

#include "diag/diagnostic.h"
#include "driver/html_report/html_report.h"
#include "source/source_manager.h"

namespace shaderport::driver {

StepStatus StatusOf(const DiagnosticList& diagnostics);

// Clang-style text of `diagnostics` (no summary line: the badges say it).
std::string DiagnosticText(const SourceFile* file, DiagnosticList diagnostics,
                           const SourceManager& sources);

}  // namespace shaderport::driver
