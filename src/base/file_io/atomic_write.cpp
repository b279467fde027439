#include "base/file_io/atomic_write.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstring>
#include <fstream>
#include <optional>

#include "base/file_io/write_temporaries.h"

namespace shaderport::file_io {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxSymlinkHops = 40;  // the kernel's own limit before ELOOP
constexpr int kMaxNameAttempts = 100;

// Keeps SIGXFSZ blocked on this thread, so that a write past RLIMIT_FSIZE fails
// with EFBIG instead of killing the process; the signal that write raised is
// discarded before the caller's mask returns.
class FileSizeSignalBlock {
 public:
  FileSizeSignalBlock() {
    sigemptyset(&signal_);
    sigaddset(&signal_, SIGXFSZ);
    pthread_sigmask(SIG_BLOCK, &signal_, &previous_);
  }
  ~FileSizeSignalBlock() {
    if (sigismember(&previous_, SIGXFSZ) == 0) {
      const timespec no_wait{0, 0};
      while (sigtimedwait(&signal_, nullptr, &no_wait) == SIGXFSZ) {
      }
    }
    pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
  }
  FileSizeSignalBlock(const FileSizeSignalBlock&) = delete;
  FileSizeSignalBlock& operator=(const FileSizeSignalBlock&) = delete;

 private:
  sigset_t signal_{};
  sigset_t previous_{};
};

// The descriptors of one write, closed (and a named temporary removed) however it ends.
struct Staging {
  int directory_fd = -1;
  int fd = -1;
  std::string temporary;  // a named temporary not yet renamed over the target
  Staging() = default;
  Staging(const Staging&) = delete;
  Staging& operator=(const Staging&) = delete;
  ~Staging() {
    if (!temporary.empty()) ::unlinkat(directory_fd, temporary.c_str(), 0);
    if (fd >= 0) ::close(fd);
    if (directory_fd >= 0) ::close(directory_fd);
  }
};

// The file a write to `path` lands in: symlinks followed, a dangling one naming
// the file to create.
std::optional<fs::path> FollowSymlinks(const fs::path& path, std::string& error) {
  fs::path current = path;
  for (int hop = 0; hop <= kMaxSymlinkHops; ++hop) {
    struct stat info {};
    if (::lstat(current.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) return current;
    std::string target(PATH_MAX, '\0');
    const ssize_t size = ::readlink(current.c_str(), target.data(), target.size());
    if (size < 0) {
      error = "cannot write " + path.string() + " (reading the symbolic link " + current.string() +
              "): " + std::strerror(errno) + "; nothing was written";
      return std::nullopt;
    }
    target.resize(static_cast<size_t>(size));
    current = current.parent_path() / fs::path(target);  // an absolute target replaces
  }
  error = "cannot write " + path.string() + ": " + std::strerror(ELOOP) + "; nothing was written";
  return std::nullopt;
}

// The mode a new file gets: 0666 less the umask, read without changing it.
mode_t ReadNewFileMode() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("Umask:", 0) == 0) {
      return static_cast<mode_t>(0666 & ~std::stoul(line.substr(6), nullptr, 8));
    }
  }
  return 0644;
}

// Read once: shaderport never changes its umask, and a run that fills the result
// cache creates thousands of files.
mode_t NewFileMode() {
  static const mode_t mode = ReadNewFileMode();
  return mode;
}

// An O_TMPFILE inode in the directory; -1 with errno EOPNOTSUPP where the
// kernel (EISDIR) or the file system (EOPNOTSUPP, EINVAL) has none.
int OpenAnonymous(int directory_fd) {
  const int fd = ::openat(directory_fd, ".", O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  if (fd < 0 && (errno == EISDIR || errno == EINVAL)) errno = EOPNOTSUPP;
  return fd;
}

int OpenNamed(int directory_fd, const std::string& target_name, std::string& name) {
  for (int attempt = 0; attempt < kMaxNameAttempts; ++attempt) {
    name = TemporaryNameFor(target_name);
    const int fd =
        ::openat(directory_fd, name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd >= 0) return fd;
    if (errno != EEXIST) break;
  }
  name.clear();
  return -1;
}

// Names the anonymous inode `fd` in the directory; false with errno.
bool LinkAnonymous(int fd, int directory_fd, const std::string& name) {
  const std::string self = "/proc/self/fd/" + std::to_string(fd);
  if (::linkat(AT_FDCWD, self.c_str(), directory_fd, name.c_str(), AT_SYMLINK_FOLLOW) == 0) {
    return true;
  }
  if (errno != ENOENT) return false;
  // No /proc: AT_EMPTY_PATH does the same but needs CAP_DAC_READ_SEARCH.
  return ::linkat(fd, "", directory_fd, name.c_str(), AT_EMPTY_PATH) == 0;
}

// Names the anonymous inode `fd` with a fresh temporary name (kept in `name`).
bool LinkAnonymousTemporary(int fd, int directory_fd, const std::string& target_name,
                            std::string& name) {
  for (int attempt = 0; attempt < kMaxNameAttempts; ++attempt) {
    const std::string candidate = TemporaryNameFor(target_name);
    if (LinkAnonymous(fd, directory_fd, candidate)) {
      name = candidate;
      return true;
    }
    if (errno != EEXIST) return false;
  }
  return false;
}

bool WriteAll(int fd, std::string_view text) {
  size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return false;
    if (n == 0) {
      errno = ENOSPC;
      return false;
    }
    written += static_cast<size_t>(n);
  }
  return true;
}

// Writes `text` to the device or FIFO `path` as it is. Opened without blocking, so
// a FIFO nobody reads is an error (ENXIO), not a hang; then written blocking.
std::string WriteToStream(const fs::path& path, std::string_view text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  int error = errno;
  bool written = false;
  if (fd >= 0) {
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    const FileSizeSignalBlock file_size_signal;
    written = WriteAll(fd, text);
    error = errno;
    ::close(fd);
  }
  if (written) return {};
  return "cannot write " + path.string() + ": " + std::strerror(error);
}

}  // namespace

std::string WriteFileAtomically(const fs::path& path, std::string_view text,
                                const AtomicWriteOptions& options) {
  // /dev/null, /dev/stdout (a link to a pipe), a FIFO: a stream, no old text to keep.
  struct stat followed {};
  if (options.user_named_target && ::stat(path.c_str(), &followed) == 0 &&
      (S_ISCHR(followed.st_mode) || S_ISFIFO(followed.st_mode))) {
    return WriteToStream(path, text);
  }
  std::string error;
  const std::optional<fs::path> target =
      options.user_named_target ? FollowSymlinks(path, error) : std::optional<fs::path>(path);
  if (!target) return error;
  const fs::path directory = target->has_parent_path() ? target->parent_path() : fs::path(".");
  const std::string name = target->filename().string();
  bool existed = false;
  auto fail = [&](const std::string& step, int code) {
    return "cannot write " + path.string() + " (" + step + "): " + std::strerror(code) +
           (existed ? "; the file is unchanged" : "; nothing was written");
  };

  Staging staging;
  staging.directory_fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (staging.directory_fd < 0) return fail("opening the directory " + directory.string(), errno);
  struct stat old {};
  if (::fstatat(staging.directory_fd, name.c_str(), &old, AT_SYMLINK_NOFOLLOW) == 0) {
    existed = true;
  } else if (errno != ENOENT) {
    return fail("reading its status", errno);
  }
  if (existed && !S_ISREG(old.st_mode)) {
    return fail("not a regular file", S_ISDIR(old.st_mode) ? EISDIR : EINVAL);
  }
  // rename() would replace a read-only file; its owner made it read-only to keep it.
  // The mode bits are asked too: access() lets root write anything.
  if (existed && ((old.st_mode & 0222) == 0 ||
                  ::faccessat(staging.directory_fd, name.c_str(), W_OK, AT_EACCESS) != 0)) {
    return fail("the file is read-only", EACCES);
  }
  RemoveStaleTemporaries(staging.directory_fd, directory);

  const FileSizeSignalBlock file_size_signal;
  staging.fd = options.anonymous_temporary ? OpenAnonymous(staging.directory_fd) : -1;
  const bool anonymous = staging.fd >= 0;
  if (!anonymous && options.anonymous_temporary && errno != EOPNOTSUPP) {
    return fail("creating a temporary file in " + directory.string(), errno);
  }
  if (!anonymous) {
    staging.fd = OpenNamed(staging.directory_fd, name, staging.temporary);
    if (staging.fd < 0) return fail("creating a temporary file in " + directory.string(), errno);
  }

  if (existed) {
    struct stat fresh {};
    if (::fstat(staging.fd, &fresh) != 0) return fail("reading the temporary's status", errno);
    const bool same_owner = fresh.st_uid == old.st_uid && fresh.st_gid == old.st_gid;
    // Only root may give a file away; a group we are not in is lost silently
    // when the file is ours anyway, as editors do.
    if (!same_owner && ::fchown(staging.fd, old.st_uid, old.st_gid) != 0 &&
        !(errno == EPERM && old.st_uid == ::geteuid())) {
      return fail("keeping its owner uid " + std::to_string(old.st_uid) + ", gid " +
                      std::to_string(old.st_gid),
                  errno);
    }
  }
  const mode_t mode = existed ? (old.st_mode & 07777) : NewFileMode();
  if (::fchmod(staging.fd, mode) != 0) return fail("setting the mode", errno);
  if (!WriteAll(staging.fd, text)) return fail("writing the new text", errno);
  if (options.sync_to_disk && ::fsync(staging.fd) != 0) {
    return fail("syncing the new text to disk", errno);
  }

  if (anonymous) {
    // A new file appears complete under its own name at once; an existing one is
    // replaced by a rename, which needs a name to rename from.
    const bool linked_in_place = !existed && LinkAnonymous(staging.fd, staging.directory_fd, name);
    if (!linked_in_place && !existed && errno != EEXIST) return fail("naming the new file", errno);
    if (!linked_in_place &&
        !LinkAnonymousTemporary(staging.fd, staging.directory_fd, name, staging.temporary)) {
      return fail("naming the temporary file", errno);
    }
  }
  if (!staging.temporary.empty()) {
    if (::renameat(staging.directory_fd, staging.temporary.c_str(), staging.directory_fd,
                   name.c_str()) != 0) {
      return fail("renaming the temporary over it", errno);
    }
    staging.temporary.clear();
  }
  // Makes the rename durable. A failure is not reported: the file already holds
  // the complete new text, and a crash could at worst bring back the old one.
  if (options.sync_to_disk) ::fsync(staging.directory_fd);
  return {};
}

}  // namespace shaderport::file_io
