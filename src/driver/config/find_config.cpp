#include "driver/config/find_config.h"

#include <system_error>

#include "base/file_io/read_regular_file.h"

namespace shaderport::driver {

std::optional<std::filesystem::path> FindConfigFor(const std::filesystem::path& file) {
  std::error_code error;
  std::filesystem::path directory = std::filesystem::absolute(file, error).lexically_normal();
  if (error) return std::nullopt;
  if (!std::filesystem::is_directory(directory, error)) directory = directory.parent_path();
  // Bounded by the depth of the path: parent_path() of the root is the root.
  while (true) {
    const std::filesystem::path candidate = directory / kConfigFileName;
    if (std::filesystem::is_regular_file(candidate, error)) return candidate;
    if (directory == directory.parent_path() || directory.empty()) return std::nullopt;
    directory = directory.parent_path();
  }
}

ConfigResult LoadConfig(const std::filesystem::path& path, SourceManager& sources) {
  auto failure = [&](std::string message) {
    ConfigResult result;
    result.config.directory = path.parent_path();
    Diagnostic d;
    d.rule_id = "config/syntax-error";
    d.message = std::move(message);
    result.diagnostics.push_back(std::move(d));
    return result;
  };
  file_io::ReadResult read = file_io::ReadRegularFile(path, kMaxConfigBytes);
  if (read.failure == file_io::ReadFailure::kTooLarge) {
    return failure(path.string() + " is larger than " + std::to_string(kMaxConfigBytes) +
                   " bytes; it is not read");
  }
  if (!read.bytes) return failure("cannot read " + path.string() + ": " + read.message);
  return ParseConfig(*read.bytes, path.string(), sources);
}

}  // namespace shaderport::driver
