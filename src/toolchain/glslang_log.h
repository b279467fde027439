// Turns a glslang info log into diagnostics that point at lines of one file.
#pragma once

#include <string_view>

#include "diag/diagnostic.h"
#include "source/source_file.h"

namespace shaderport::toolchain {

// Every "ERROR: <string>:<line>: <text>" line of `log` becomes a diagnostic with `rule_id` and
// `severity`, its message `prefix` + glslang's text, on that line of `file`. Warnings and the
// summary lines ("N compilation errors") are skipped. A log with errors but no parsable line
// still yields one diagnostic, so a failure is never silent.
void AppendGlslangErrors(std::string_view log, const SourceFile& file, std::string_view rule_id,
                         Severity severity, std::string_view prefix, DiagnosticList& out);

}  // namespace shaderport::toolchain
