#include "driver/port/file_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <utility>

namespace shaderport::driver {
namespace {

// Replacements seen while waiting before giving up on locking (each one is
// another process finishing its write, so this is never reached in practice).
constexpr int kMaxReplacements = 1000;

bool SameFile(const struct stat& a, const struct stat& b) {
  return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

}  // namespace

FileUpdateLock::FileUpdateLock(const std::filesystem::path& path) {
  for (int attempt = 0; attempt < kMaxReplacements; ++attempt) {
    // O_NONBLOCK: opening a FIFO must not wait for a writer.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) return;
    struct stat locked {};
    if (::fstat(fd, &locked) != 0 || !S_ISREG(locked.st_mode)) {
      ::close(fd);
      return;
    }
    int status = 0;
    while ((status = ::flock(fd, LOCK_EX)) != 0 && errno == EINTR) {
    }
    struct stat now {};
    if (status != 0 || ::stat(path.c_str(), &now) != 0 || SameFile(locked, now)) {
      if (status == 0) {
        fd_ = fd;
      } else {
        ::close(fd);
      }
      return;
    }
    ::close(fd);  // replaced while we waited: lock the file the path names now
  }
}

FileUpdateLock::~FileUpdateLock() {
  if (fd_ >= 0) ::close(fd_);
}

FileUpdateLock::FileUpdateLock(FileUpdateLock&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)) {}

FileUpdateLock& FileUpdateLock::operator=(FileUpdateLock&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = std::exchange(other.fd_, -1);
  }
  return *this;
}

}  // namespace shaderport::driver
