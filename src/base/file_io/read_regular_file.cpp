#include "base/file_io/read_regular_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace shaderport::file_io {
namespace {

ReadResult Failed(ReadFailure failure, std::string message) {
  ReadResult result;
  result.failure = failure;
  result.message = std::move(message);
  return result;
}

// Closes the descriptor however the read ends.
struct Descriptor {
  int fd = -1;
  explicit Descriptor(int opened) : fd(opened) {}
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

const char* KindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  return "a device or special file";
}

}  // namespace

std::string SizeLimitText(size_t bytes) {
  if (bytes >= (size_t{1} << 20) && bytes % (size_t{1} << 20) == 0) {
    return std::to_string(bytes >> 20) + " MiB";
  }
  if (bytes >= 1024 && bytes % 1024 == 0) return std::to_string(bytes >> 10) + " KiB";
  return std::to_string(bytes) + " bytes";
}

ReadResult ReadRegularFile(const std::filesystem::path& path, size_t max_bytes) {
  const Descriptor file(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
  if (file.fd < 0) {
    return Failed(ReadFailure::kCannotOpen,
                  std::string("cannot open file: ") + std::strerror(errno));
  }
  struct stat info {};
  if (::fstat(file.fd, &info) != 0) {
    return Failed(ReadFailure::kCannotRead,
                  std::string("cannot read file: ") + std::strerror(errno));
  }
  if (!S_ISREG(info.st_mode)) {
    return Failed(ReadFailure::kNotRegular,
                  std::string("not a regular file: ") + KindOf(info.st_mode));
  }
  const auto size = static_cast<uintmax_t>(info.st_size);
  if (size > max_bytes) {
    ReadResult result = Failed(ReadFailure::kTooLarge,
                               "file is larger than the " + SizeLimitText(max_bytes) + " limit");
    result.size = size;
    return result;
  }
  // One byte more than fstat said: a file that grew since is noticed, not cut short.
  std::string bytes(static_cast<size_t>(size) + 1, '\0');
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(file.fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      return Failed(ReadFailure::kCannotRead,
                    std::string("cannot read file: ") + std::strerror(errno));
    }
    if (n == 0) break;
    done += static_cast<size_t>(n);
  }
  if (done != size) return Failed(ReadFailure::kChangedSize, "file changed size while being read");
  bytes.resize(done);
  ReadResult result;
  result.bytes = std::move(bytes);
  return result;
}

std::string ReadRegularFileHead(const std::filesystem::path& path, size_t max_bytes) {
  const Descriptor file(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
  struct stat info {};
  if (file.fd < 0 || ::fstat(file.fd, &info) != 0 || !S_ISREG(info.st_mode)) return "";
  std::string head(max_bytes, '\0');
  size_t done = 0;
  while (done < head.size()) {
    const ssize_t n = ::read(file.fd, head.data() + done, head.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += static_cast<size_t>(n);
  }
  head.resize(done);
  return head;
}

}  // namespace shaderport::file_io
