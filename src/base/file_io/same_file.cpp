#include "base/file_io/same_file.h"

#include <sys/stat.h>

namespace shaderport::file_io {

std::optional<FileIdentity> IdentityOf(const std::filesystem::path& path) {
  struct stat info {};
  if (path.empty() || ::stat(path.c_str(), &info) != 0) return std::nullopt;
  return FileIdentity{info.st_dev, info.st_ino};
}

std::optional<std::filesystem::path> InputReplacedBy(
    const std::filesystem::path& output, std::span<const std::filesystem::path> inputs) {
  const std::optional<FileIdentity> written = IdentityOf(output);
  if (!written) return std::nullopt;
  for (const std::filesystem::path& input : inputs) {
    if (IdentityOf(input) == written) return input;
  }
  return std::nullopt;
}

}  // namespace shaderport::file_io
