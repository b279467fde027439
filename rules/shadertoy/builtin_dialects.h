// The harness dialects shipped in rules/dialects/*.toml, and `--dialect NAME|FILE`.
#pragma once

#include <span>
#include <string_view>

#include "rule/harness_dialect.h"
#include "source/source_manager.h"

namespace shaderport::rules {

// Every shipped dialect, sorted by name; loaded once (thread-safe) from the
// dialects directory. A shipped file with errors is left out (a test guards this).
std::span<const rule::HarnessDialect> BuiltinDialects();

// By name or alias ("shadertoy", "raymarch-harness"); nullptr when unknown.
const rule::HarnessDialect* FindBuiltinDialect(std::string_view name);

// For `--dialect`: a shipped dialect's name, else a TOML file's path (added to
// `sources` so that its errors have a location). An unknown name that is no
// readable file gives a `dialect/not-found` error.
rule::DialectLoadResult LoadDialect(std::string_view name_or_path, SourceManager& sources);

// Where the shipped dialect files are (the source tree's rules/dialects).
std::string_view DialectsDirectory();

}  // namespace shaderport::rules
