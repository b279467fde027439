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

namespace {

// The files under `root`, sorted, or an error message.
std::vector<fs::path> WalkDirectory(const fs::path& root, std::string& error_message) {
  std::vector<fs::path> found;
  std::error_code error;
  fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, error);
  for (; !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
    // Hidden directories (.git, .cache) never hold shaders a user wants checked.
    if (it->is_directory() && it->path().filename().string().starts_with(".")) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file() && IsShaderExtension(it->path())) found.push_back(it->path());
  }
  if (error) error_message = root.string() + ": " + error.message();
  std::sort(found.begin(), found.end());
  return found;
}

}  // namespace

InputSet WalkInputs(const std::vector<fs::path>& paths, const KeepWalkedFile& keep) {
  InputSet result;
  std::set<fs::path> seen;
  auto add = [&](InputFile file) {
    if (seen.insert(file.path.lexically_normal()).second) result.files.push_back(std::move(file));
  };
  for (const fs::path& path : paths) {
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (error || status.type() == fs::file_type::not_found) {
      result.errors.push_back(path.string() + ": no such file or directory");
      continue;
    }
    if (!fs::is_directory(status)) {
      add({path, path.lexically_normal(), true});
      continue;
    }
    std::string walk_error;
    for (const fs::path& file : WalkDirectory(path, walk_error)) {
      if (keep && !keep(file)) continue;
      add({file, file.lexically_relative(path), false});
    }
    if (!walk_error.empty()) result.errors.push_back(std::move(walk_error));
  }
  return result;
}

InputFileList CollectInputFiles(const std::vector<fs::path>& paths) {
  InputSet inputs = WalkInputs(paths);
  InputFileList result;
  for (InputFile& file : inputs.files) result.files.push_back(std::move(file.path));
  result.errors = std::move(inputs.errors);
  return result;
}

}  // namespace shaderport::driver
