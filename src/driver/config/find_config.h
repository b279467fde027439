// The file-system side of .shaderport.toml: finding and reading it.
#pragma once

#include <filesystem>
#include <optional>

#include "base/limits.h"
#include "driver/config/config.h"
#include "source/source_manager.h"

namespace shaderport::driver {

// Largest config file read; anything bigger is not a hand-written config.
inline constexpr uintmax_t kMaxConfigBytes = limits::kMaxConfigBytes;

// The nearest .shaderport.toml in the directory of `file` or any parent, as
// ESLint and clang-tidy look for theirs; nullopt when there is none up to the root.
std::optional<std::filesystem::path> FindConfigFor(const std::filesystem::path& file);

// Reads and parses `path`. An unreadable or oversized file is a config/syntax-error
// diagnostic with no location, and the default Config.
ConfigResult LoadConfig(const std::filesystem::path& path, SourceManager& sources);

}  // namespace shaderport::driver
