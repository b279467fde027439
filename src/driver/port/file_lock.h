// Serialising the read-modify-write of one file (`fix --in-place`) between
// shaderport processes.
#pragma once

#include <filesystem>

namespace shaderport::driver {

// An exclusive advisory lock (flock) on the file a path names, held until
// destruction. Waits for another holder; when that holder replaced the file
// meanwhile (WriteFileAtomically renames a new inode in), locks the new file
// instead, so the caller then reads the text the other process wrote.
// A path that cannot be opened or is not a regular file, or a file system
// without flock, gives a lock that holds nothing: reading the file reports
// the problem, and such files were never serialised.
class FileUpdateLock {
 public:
  FileUpdateLock() = default;
  explicit FileUpdateLock(const std::filesystem::path& path);
  ~FileUpdateLock();
  FileUpdateLock(FileUpdateLock&& other) noexcept;
  FileUpdateLock& operator=(FileUpdateLock&& other) noexcept;
  FileUpdateLock(const FileUpdateLock&) = delete;
  FileUpdateLock& operator=(const FileUpdateLock&) = delete;

  bool Held() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

}  // namespace shaderport::driver
