// A harness dialect named on a command line (`--dialect NAME|FILE`): a shipped one,
// or one read from a TOML file with its problems as diagnostics located there. The dialect itself
// and its TOML reader are in model/harness_dialect.h.
#pragma once

#include <optional>
#include <string_view>

#include "diag/diagnostic.h"
#include "model/harness_dialect.h"
#include "source/source_file.h"
#include "source/source_manager.h"

namespace shaderport::rule {

struct DialectLoadResult {
  std::optional<model::HarnessDialect> dialect;  // absent when the file has errors
  DiagnosticList diagnostics;                    // errors in the TOML, located in the file
};

// Parses a dialect from `file`'s TOML. Errors are `dialect/...` diagnostics at the
// offending line and column; unknown keys are warnings.
DialectLoadResult ParseDialect(const SourceFile& file);

// A shipped dialect's name or alias, else a TOML file's path (added to `sources` so
// that its errors have a location). An unknown name that is no readable file gives a
// `dialect/not-found` error.
DialectLoadResult LoadDialect(std::string_view name_or_path, SourceManager& sources);

}  // namespace shaderport::rule
