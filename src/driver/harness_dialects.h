// The harness dialects a command line can name with --dialect (rules/dialects/*.toml
// shipped in the binary, or a TOML file), for the CLI, which reaches rules/ only
// through the driver.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "rule/harness_dialect_file.h"
#include "source/source_manager.h"

namespace shaderport::driver {

// The names and aliases of the shipped harness dialects.
std::vector<std::string> ShippedHarnessDialectNames();

// A shipped dialect by name or alias, else a TOML file's path (added to `sources`
// so that its errors have a location); `dialect/not-found` when it is neither.
rule::DialectLoadResult LoadHarnessDialect(std::string_view name_or_path, SourceManager& sources);

}  // namespace shaderport::driver
