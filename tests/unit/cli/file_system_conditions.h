// Real file-system conditions for write tests: an immutable file or directory
// (what stops root too), a tiny tmpfs (a full disk), directory listings, and
// large shaders with many fixes.
#pragma once

#include <fcntl.h>
#include <linux/fs.h>
#include <sys/ioctl.h>
#include <sys/mount.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace shaderport::testing {

// Sets FS_IMMUTABLE_FL on `path` until destruction (needs CAP_LINUX_IMMUTABLE
// and a file system that has the flag); Active() says whether it took.
class ImmutableFlag {
 public:
  explicit ImmutableFlag(const std::filesystem::path& path) : path_(path) { active_ = Set(true); }
  ~ImmutableFlag() {
    if (active_) Set(false);
  }
  ImmutableFlag(const ImmutableFlag&) = delete;
  ImmutableFlag& operator=(const ImmutableFlag&) = delete;
  bool Active() const { return active_; }

 private:
  bool Set(bool on) {
    const int fd = ::open(path_.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return false;
    int flags = 0;
    bool done = ::ioctl(fd, FS_IOC_GETFLAGS, &flags) == 0;
    flags = on ? (flags | FS_IMMUTABLE_FL) : (flags & ~FS_IMMUTABLE_FL);
    done = done && ::ioctl(fd, FS_IOC_SETFLAGS, &flags) == 0;
    ::close(fd);
    return done;
  }
  std::filesystem::path path_;
  bool active_ = false;
};

// A tmpfs of `bytes` mounted on `directory` until destruction (needs
// CAP_SYS_ADMIN); Active() says whether the mount worked.
class TinyTmpfs {
 public:
  TinyTmpfs(const std::filesystem::path& directory, size_t bytes) : directory_(directory) {
    const std::string size = "size=" + std::to_string(bytes) + ",mode=0755";
    active_ = ::mount("tmpfs", directory.c_str(), "tmpfs", 0, size.c_str()) == 0;
  }
  ~TinyTmpfs() {
    if (active_) ::umount2(directory_.c_str(), MNT_DETACH);
  }
  TinyTmpfs(const TinyTmpfs&) = delete;
  TinyTmpfs& operator=(const TinyTmpfs&) = delete;
  bool Active() const { return active_; }

 private:
  std::filesystem::path directory_;
  bool active_ = false;
};

// The names in `directory`, sorted.
inline std::vector<std::string> EntriesOf(const std::filesystem::path& directory) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// A ShaderToy pass of about `padding_bytes` of comment followed by `functions`
// functions whose int literals `fix` turns into floats (three per function).
inline std::string FixableShaderToy(size_t padding_bytes, int functions) {
  const std::string line = "// generated padding: fix must copy every byte of this text\n";
  std::string text;
  text.reserve(padding_bytes + static_cast<size_t>(functions) * 80 + 200);
  while (text.size() < padding_bytes) text += line;
  for (int i = 0; i < functions; ++i) {
    const std::string n = std::to_string(i);
    text += "float f" + n + "(float a) {\n  float x = " + std::to_string(i % 7) +
            ";\n  float y = a * 2 + x;\n  return y / 3;\n}\n";
  }
  text +=
      "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
      "  fragColor = vec4(f0(fragCoord.x), 0, 0, 1);\n}\n";
  return text;
}

}  // namespace shaderport::testing
