#include "driver/result_cache.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <system_error>
#include <vector>

#include "driver/cache_entry.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kTemporaryPrefix = ".tmp-";
constexpr std::string_view kPruneStamp = ".last-prune";
// An entry larger than this is not one we wrote.
constexpr off_t kMaxEntryFileBytes = 64 << 20;

bool WriteAll(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    bytes.remove_prefix(static_cast<size_t>(written));
  }
  return true;
}

// The standard marker that tells backup and archiving tools to skip the directory.
void TagCacheDirectory(const fs::path& directory) {
  const fs::path tag = directory / "CACHEDIR.TAG";
  std::error_code error;
  if (fs::exists(tag, error)) return;
  std::ofstream(tag) << "Signature: 8a477f597d28d172789f06886806bc55\n"
                        "# This file is a cache directory tag created by shaderport.\n";
}

struct EntryFile {
  fs::path path;
  fs::file_time_type written;
  uintmax_t size = 0;
};

}  // namespace

std::optional<fs::path> DefaultCacheDirectory(const char* xdg_cache_home, const char* home) {
  if (xdg_cache_home != nullptr && fs::path(xdg_cache_home).is_absolute()) {
    return fs::path(xdg_cache_home) / "shaderport";
  }
  if (home != nullptr && *home != '\0') return fs::path(home) / ".cache" / "shaderport";
  return std::nullopt;
}

ResultCache::ResultCache(fs::path directory)
    : directory_(std::move(directory)),
      entries_(directory_ / ("v" + std::to_string(kCacheEntryVersion))) {}

fs::path ResultCache::EntryPath(const CacheKey& key) const {
  const std::string hex = key.Hex();
  return entries_ / hex.substr(0, 2) / hex;
}

std::optional<std::string> ResultCache::Load(const CacheKey& key) const {
  const int fd = ::open(EntryPath(key).c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  std::optional<std::string> bytes;
  struct stat status {};
  if (::fstat(fd, &status) == 0 && S_ISREG(status.st_mode) &&
      status.st_size <= kMaxEntryFileBytes) {
    std::string buffer(static_cast<size_t>(status.st_size), '\0');
    size_t done = 0;
    while (done < buffer.size()) {
      const ssize_t got = ::read(fd, buffer.data() + done, buffer.size() - done);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) break;
      done += static_cast<size_t>(got);
    }
    if (done == buffer.size()) bytes = std::move(buffer);
  }
  ::close(fd);
  return bytes;
}

bool ResultCache::Store(const CacheKey& key, std::string_view bytes) const {
  const fs::path target = EntryPath(key);
  std::error_code error;
  if (!fs::is_directory(target.parent_path(), error)) {
    fs::create_directories(target.parent_path(), error);
    if (error) return false;
    TagCacheDirectory(directory_);
  }
  std::string temporary = (target.parent_path() / kTemporaryPrefix).string() + "XXXXXX";
  const int fd = ::mkstemp(temporary.data());
  if (fd < 0) return false;
  const bool written = WriteAll(fd, bytes);
  const bool closed = ::close(fd) == 0;
  if (!written || !closed || ::rename(temporary.c_str(), target.c_str()) != 0) {
    ::unlink(temporary.c_str());
    return false;
  }
  return true;
}

void ResultCache::Prune(const CacheLimits& limits, fs::file_time_type now) const {
  std::error_code error;
  const fs::path stamp = entries_ / kPruneStamp;
  const fs::file_time_type last = fs::last_write_time(stamp, error);
  if (!error && now - last < limits.prune_interval) return;
  if (!fs::is_directory(entries_, error)) return;
  std::ofstream{stamp};  // claim this prune before the walk, so concurrent runs skip it
  fs::last_write_time(stamp, now, error);

  std::vector<EntryFile> entries;
  uintmax_t total = 0;
  fs::recursive_directory_iterator it(entries_, error);
  for (; !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
    std::error_code entry_error;  // one unreadable entry must not stop the walk
    if (!it->is_regular_file(entry_error) || it->path() == stamp) continue;
    const fs::file_time_type written = it->last_write_time(entry_error);
    const uintmax_t size = it->file_size(entry_error);
    if (entry_error) continue;
    const bool temporary = it->path().filename().string().starts_with(kTemporaryPrefix);
    // A temporary file an hour old belongs to a run that died before its rename.
    const auto limit = temporary ? std::chrono::hours(1) : limits.max_age;
    if (now - written > limit) {
      fs::remove(it->path(), entry_error);
      continue;
    }
    entries.push_back({it->path(), written, size});
    total += size;
  }
  if (total <= limits.max_bytes) return;
  std::sort(entries.begin(), entries.end(),
            [](const EntryFile& a, const EntryFile& b) { return a.written < b.written; });
  for (const EntryFile& entry : entries) {
    if (total <= limits.max_bytes / 4 * 3) break;
    std::error_code entry_error;
    if (fs::remove(entry.path, entry_error)) total -= entry.size;
  }
}

}  // namespace shaderport::driver
