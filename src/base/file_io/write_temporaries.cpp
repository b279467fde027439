#include "base/file_io/write_temporaries.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <ctime>
#include <mutex>
#include <random>
#include <set>

#include "base/file_io/atomic_write.h"

namespace shaderport::file_io {
namespace {

constexpr std::string_view kMarker = ".shaderport-";
constexpr std::string_view kSuffix = ".tmp";
constexpr size_t kRandomChars = 6;

bool AllOf(std::string_view text, int (*predicate)(int)) {
  for (const char c : text) {
    if (predicate(static_cast<unsigned char>(c)) == 0) return false;
  }
  return !text.empty();
}

}  // namespace

std::string TemporaryNameFor(std::string_view target_name) {
  static constexpr std::string_view kAlphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  thread_local std::mt19937_64 random{std::random_device{}()};
  std::string name =
      "." + std::string(target_name) + std::string(kMarker) + std::to_string(::getpid()) + "-";
  for (size_t i = 0; i < kRandomChars; ++i) name += kAlphabet[random() % kAlphabet.size()];
  return name + std::string(kSuffix);
}

bool IsAtomicWriteTemporary(std::string_view name) {
  // Parsed from the end: the target's own name may contain anything.
  if (name.size() < kSuffix.size() || name.substr(name.size() - kSuffix.size()) != kSuffix) {
    return false;
  }
  name.remove_suffix(kSuffix.size());
  if (name.size() < kRandomChars) return false;
  if (!AllOf(name.substr(name.size() - kRandomChars), &isalnum)) return false;
  name.remove_suffix(kRandomChars);
  if (name.empty() || name.back() != '-') return false;
  name.remove_suffix(1);
  const size_t marker = name.rfind(kMarker);
  if (marker == std::string_view::npos) return false;
  if (!AllOf(name.substr(marker + kMarker.size()), &isdigit)) return false;
  return marker >= 2 && name.front() == '.';  // "." and a non-empty target name
}

void RemoveStaleTemporaries(int directory_fd, const std::filesystem::path& directory) {
  // Keyed by path, not inode: a directory removed and made again may reuse the inode.
  std::error_code error;
  const std::filesystem::path key = std::filesystem::absolute(directory, error).lexically_normal();
  static std::mutex mutex;
  static std::set<std::filesystem::path> done;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (!done.insert(key).second) return;
  }
  const int listing_fd = ::openat(directory_fd, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (listing_fd < 0) return;
  DIR* listing = ::fdopendir(listing_fd);
  if (listing == nullptr) {
    ::close(listing_fd);
    return;
  }
  const std::time_t stale_before =
      std::time(nullptr) -
      std::chrono::duration_cast<std::chrono::seconds>(kStaleTemporaryAge).count();
  while (const dirent* entry = ::readdir(listing)) {
    if (!IsAtomicWriteTemporary(entry->d_name)) continue;
    struct stat info {};
    // Only regular files, and only old ones: a young one may be another
    // process's write in progress.
    if (::fstatat(directory_fd, entry->d_name, &info, AT_SYMLINK_NOFOLLOW) == 0 &&
        S_ISREG(info.st_mode) && info.st_mtime < stale_before) {
      ::unlinkat(directory_fd, entry->d_name, 0);
    }
  }
  ::closedir(listing);
}

}  // namespace shaderport::file_io
