// The harness dialects shipped in rules/dialects/*.toml, and `--dialect NAME|FILE`.
#pragma once

#include <span>
#include <string_view>

#include "rule/harness_dialect.h"
#include "source/source_manager.h"

namespace shaderport::rules {

// Every shipped dialect, sorted by name; parsed once (thread-safe) from the
// copies compiled into the binary. A shipped file with errors is left out (a
// test guards this).
std::span<const rule::HarnessDialect> BuiltinDialects();

// By name or alias ("shadertoy", "raymarch-harness"); nullptr when unknown.
const rule::HarnessDialect* FindBuiltinDialect(std::string_view name);

// For `--dialect`: a shipped dialect's name, else a TOML file's path (added to
// `sources` so that its errors have a location). An unknown name that is no
// readable file gives a `dialect/not-found` error.
rule::DialectLoadResult LoadDialect(std::string_view name_or_path, SourceManager& sources);

// The source tree's rules/dialects, where tests read the shipped files.
std::string_view DialectsDirectory();

}  // namespace shaderport::rules
