// Turns the paths a user gives into the list of shader files to process.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace shaderport::driver {

// Extensions `check` picks up when it walks a directory.
bool IsShaderExtension(const std::filesystem::path& path);

struct InputFileList {
  std::vector<std::filesystem::path> files;  // sorted, without duplicates
  std::vector<std::string> errors;           // paths that do not exist, unreadable directories
};

// Files named directly are taken whatever their extension; directories are walked
// recursively for shader extensions. The order is deterministic (sorted per argument).
InputFileList CollectInputFiles(const std::vector<std::filesystem::path>& paths);

}  // namespace shaderport::driver
