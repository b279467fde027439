#include "driver/config/find_config.h"

#include <fstream>
#include <sstream>
#include <system_error>

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
  std::error_code error;
  const uintmax_t size = std::filesystem::file_size(path, error);
  if (error) return failure("cannot read " + path.string() + ": " + error.message());
  if (size > kMaxConfigBytes) {
    return failure(path.string() + " is larger than " + std::to_string(kMaxConfigBytes) +
                   " bytes; it is not read");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return failure("cannot open " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return ParseConfig(text.str(), path.string(), sources);
}

}  // namespace shaderport::driver
