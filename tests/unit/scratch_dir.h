// Scratch directories for tests that run the binary and read what it wrote after the
// command returns: they live under one directory per test process, removed when the
// process ends, so a run leaves nothing behind in the system's temporary directory.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace shaderport::testing {

class ScratchRoot {
 public:
  static const std::filesystem::path& Path() {
    static const ScratchRoot root;
    return root.path_;
  }
  ScratchRoot(const ScratchRoot&) = delete;
  ScratchRoot& operator=(const ScratchRoot&) = delete;

 private:
  ScratchRoot()
      : path_(std::filesystem::temp_directory_path() /
              ("shaderport-scratch-" + std::to_string(::getpid()))) {}
  ~ScratchRoot() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  std::filesystem::path path_;
};

// An empty directory `name` under the process's scratch root.
inline std::filesystem::path ScratchDir(const std::string& name) {
  const std::filesystem::path dir = ScratchRoot::Path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace shaderport::testing
