#include "driver/input_files.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <string>
#include <system_error>
#include <unordered_set>

#include "base/file_io/read_regular_file.h"

namespace shaderport::driver {

namespace fs = std::filesystem;

bool IsShaderExtension(const fs::path& path) {
  static constexpr std::array<std::string_view, 7> kExtensions = {".glsl", ".frag", ".vert", ".fs",
                                                                  ".vs",   ".fsh",  ".vsh"};
  const std::string extension = path.extension().string();
  return std::find(kExtensions.begin(), kExtensions.end(), extension) != kExtensions.end();
}

namespace {

// A walked .json/.jsonl file is taken only when its start names ShaderToy's pass
// arrays: a repository's package.json or tsconfig.json is not a shader.
bool LooksLikeShaderToyDocument(const fs::path& path) {
  const std::string extension = path.extension().string();
  if (extension != ".json" && extension != ".jsonl") return false;
  const std::string head = file_io::ReadRegularFileHead(path, 65536);
  return head.find("\"renderpass\"") != std::string::npos ||
         head.find("\"passes\"") != std::string::npos;
}

// The files under `root`, sorted; what could not be walked goes to `problems`.
std::vector<fs::path> WalkDirectory(const fs::path& root, std::vector<std::string>& problems) {
  std::vector<fs::path> found;
  const size_t first_problem = problems.size();
  std::error_code error;
  fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, error);
  for (; !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
    // The error_code forms: a symbolic link loop must not throw out of the walk.
    std::error_code entry_error;
    const fs::file_status status = it->status(entry_error);
    if (entry_error && entry_error != std::errc::no_such_file_or_directory) {
      problems.push_back(it->path().string() + ": " + entry_error.message());
      continue;
    }
    if (fs::is_directory(status)) {
      // Hidden directories (.git, .cache) never hold shaders a user wants checked.
      if (it->path().filename().string().starts_with(".")) {
        it.disable_recursion_pending();
      } else if (!it->is_symlink(entry_error) && ::access(it->path().c_str(), R_OK | X_OK) != 0) {
        // Skipped by the walk; said, so that a CI run does not pass unchecked files.
        problems.push_back(it->path().string() +
                           ": directory not readable, its files are not checked");
      }
      continue;
    }
    if (fs::is_regular_file(status) &&
        (IsShaderExtension(it->path()) || LooksLikeShaderToyDocument(it->path())))
      found.push_back(it->path());
  }
  if (error) problems.push_back(root.string() + ": " + error.message());
  std::sort(problems.begin() + static_cast<std::ptrdiff_t>(first_problem), problems.end());
  std::sort(found.begin(), found.end());
  return found;
}

}  // namespace

bool IsUnmatchedPattern(const fs::path& path) {
  std::error_code error;
  return path.string().find_first_of("*?[") != std::string::npos && !fs::exists(path, error);
}

std::string MissingPathError(const fs::path& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!error && status.type() != fs::file_type::not_found) return "";
  if (IsUnmatchedPattern(path)) return path.string() + ": no file matches this pattern";
  // ELOOP and EACCES say more than "no such file".
  const bool missing = !error || error == std::errc::no_such_file_or_directory;
  return path.string() + ": " + (missing ? "no such file or directory" : error.message());
}

InputSet WalkInputs(const std::vector<fs::path>& paths, const KeepWalkedFile& keep,
                    bool filter_named) {
  InputSet result;
  // Normal forms as strings: for normalised paths, equal strings are equal paths, and a
  // hashed string is far cheaper than comparing paths component by component.
  std::unordered_set<std::string> seen;
  auto add = [&](InputFile file, const fs::path& normal) {
    if (seen.insert(normal.native()).second) result.files.push_back(std::move(file));
  };
  for (const fs::path& path : paths) {
    std::string missing = MissingPathError(path);
    if (!missing.empty()) {
      (IsUnmatchedPattern(path) ? result.unmatched : result.errors).push_back(std::move(missing));
      continue;
    }
    std::error_code error;
    if (!fs::is_directory(path, error)) {
      if (filter_named && keep && !keep(path)) {
        ++result.dropped;
        continue;
      }
      const fs::path normal = path.lexically_normal();
      add({path, normal, true}, normal);
      continue;
    }
    for (const fs::path& file : WalkDirectory(path, result.errors)) {
      if (keep && !keep(file)) {
        ++result.dropped;
        continue;
      }
      add({file, file.lexically_relative(path), false}, file.lexically_normal());
    }
  }
  return result;
}

InputFileList CollectInputFiles(const std::vector<fs::path>& paths) {
  InputSet inputs = WalkInputs(paths);
  InputFileList result;
  for (InputFile& file : inputs.files) result.files.push_back(std::move(file.path));
  result.errors = std::move(inputs.errors);
  result.errors.insert(result.errors.end(), inputs.unmatched.begin(), inputs.unmatched.end());
  return result;
}

}  // namespace shaderport::driver
