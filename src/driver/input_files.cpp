#include "driver/input_files.h"

#include <algorithm>
#include <array>
#include <set>
#include <system_error>

namespace shaderport::driver {

namespace fs = std::filesystem;

bool IsShaderExtension(const fs::path& path) {
  static constexpr std::array<std::string_view, 7> kExtensions = {".glsl", ".frag", ".vert", ".fs",
                                                                  ".vs",   ".fsh",  ".vsh"};
  const std::string extension = path.extension().string();
  return std::find(kExtensions.begin(), kExtensions.end(), extension) != kExtensions.end();
}

InputFileList CollectInputFiles(const std::vector<fs::path>& paths) {
  InputFileList result;
  std::set<fs::path> seen;
  auto add = [&](const fs::path& file) {
    if (seen.insert(file.lexically_normal()).second) result.files.push_back(file);
  };
  for (const fs::path& path : paths) {
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (error || status.type() == fs::file_type::not_found) {
      result.errors.push_back(path.string() + ": no such file or directory");
      continue;
    }
    if (!fs::is_directory(status)) {
      add(path);
      continue;
    }
    std::vector<fs::path> found;
    fs::recursive_directory_iterator it(path, fs::directory_options::skip_permission_denied, error);
    for (; !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
      // Hidden directories (.git, .cache) never hold shaders a user wants checked.
      if (it->is_directory() && it->path().filename().string().starts_with(".")) {
        it.disable_recursion_pending();
        continue;
      }
      if (it->is_regular_file() && IsShaderExtension(it->path())) found.push_back(it->path());
    }
    if (error) result.errors.push_back(path.string() + ": " + error.message());
    std::sort(found.begin(), found.end());
    for (const fs::path& file : found) add(file);
  }
  return result;
}

}  // namespace shaderport::driver
