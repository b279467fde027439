#include "driver/port/writable_path.h"

#include <unistd.h>

namespace shaderport::driver {

namespace fs = std::filesystem;

std::string UnwritablePath(const fs::path& target) {
  const std::string prefix = "cannot write " + target.string() + ": ";
  const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code error;
  const fs::file_status status = fs::status(directory, error);
  if (status.type() == fs::file_type::not_found) {
    return prefix + "no such directory " + directory.string();
  }
  if (!fs::is_directory(status)) return prefix + directory.string() + " is not a directory";
  if (::access(directory.c_str(), W_OK | X_OK) != 0) {
    return prefix + "the directory " + directory.string() + " is not writable";
  }
  if (fs::is_directory(target, error)) return prefix + "it is a directory";
  if (fs::exists(target, error) && ::access(target.c_str(), W_OK) != 0) {
    return prefix + "the file is not writable";
  }
  return "";
}

}  // namespace shaderport::driver
