// A throwaway directory of shader files for tests that run the binary.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace shaderport::testing {

class TempProject {
 public:
  explicit TempProject(const std::string& name)
      : root_(std::filesystem::temp_directory_path() /
              ("shaderport-" + name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(root_);
    std::filesystem::create_directories(root_);
  }
  ~TempProject() { std::filesystem::remove_all(root_); }
  TempProject(const TempProject&) = delete;
  TempProject& operator=(const TempProject&) = delete;

  const std::filesystem::path& Root() const { return root_; }
  std::filesystem::path Write(const std::string& relative, const std::string& text) const {
    const std::filesystem::path file = root_ / relative;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }
  bool Exists(const std::string& relative) const {
    return std::filesystem::exists(root_ / relative);
  }

 private:
  std::filesystem::path root_;
};

// A WebGL1 fragment shader that ports cleanly.
inline constexpr const char* kWebGL1Fragment =
    "precision mediump float;\nvarying vec2 uv;\nuniform sampler2D tex;\n"
    "void main() {\n  gl_FragColor = texture2D(tex, uv);\n}\n";

// GLSL ES 3.00 with an int where a float is needed: glslang rejects it
// (glslang/type-mismatch) and `fix` turns `1` into `1.0`.
inline constexpr const char* kFixableEssl3 =
    "#version 300 es\nprecision mediump float;\nout vec4 o;\n"
    "void main() { float x = 1; o = vec4(x); }\n";

// A nested shader tree whose .shaderport.toml excludes shaders/vendor/, with a
// hidden directory and a file of another extension:
//   shaders/a/b.glsl  shaders/top.frag  (taken)
//   shaders/vendor/v.frag  shaders/.hidden/h.frag  shaders/a/notes.txt  (not)
inline void WriteNestedProject(const TempProject& project, const std::string& shader) {
  project.Write(".shaderport.toml", "[check]\nexclude = [\"shaders/vendor/**\"]\n");
  project.Write("shaders/a/b.glsl", shader);
  project.Write("shaders/top.frag", shader);
  project.Write("shaders/vendor/v.frag", shader);
  project.Write("shaders/.hidden/h.frag", shader);
  project.Write("shaders/a/notes.txt", shader);
}

}  // namespace shaderport::testing
