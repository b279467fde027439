#include "base/file_io/writable_path.h"

#include <sys/stat.h>
#include <unistd.h>

namespace shaderport::file_io {

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
  // The mode bits too: access() lets root write anything, and a read-only file is
  // refused for everyone (as WriteFileAtomically does).
  struct stat info {};
  if (::stat(target.c_str(), &info) == 0 &&
      ((info.st_mode & 0222) == 0 || ::access(target.c_str(), W_OK) != 0)) {
    return prefix + "the file is read-only";
  }
  return "";
}

}  // namespace shaderport::file_io
