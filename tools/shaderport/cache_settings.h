// Where `check` keeps its result cache and what identifies this build in it.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace shaderport::cli {

// --cache-dir DIR, else $XDG_CACHE_HOME/shaderport, else ~/.cache/shaderport;
// nullopt (no cache) when none of them is known.
std::optional<std::filesystem::path> CacheDirectory(const std::string& cache_dir_option);

// The version and the executable's size and modification time: a rebuilt or
// reinstalled shaderport never reads the entries of another build.
std::string ToolIdentity();

}  // namespace shaderport::cli
