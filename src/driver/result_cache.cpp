#include "driver/result_cache.h"

#include <algorithm>
#include <system_error>
#include <vector>

#include "base/file_io/atomic_write.h"
#include "base/file_io/read_regular_file.h"
#include "base/limits.h"
#include "driver/cache_entry.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

// The temporaries of versions before the atomic writer; a crash may have left some.
constexpr std::string_view kTemporaryPrefix = ".tmp-";
constexpr std::string_view kPruneStamp = ".last-prune";

// The standard marker that tells backup and archiving tools to skip the directory.
void TagCacheDirectory(const fs::path& directory) {
  const fs::path tag = directory / "CACHEDIR.TAG";
  std::error_code error;
  if (fs::exists(tag, error)) return;
  file_io::WriteFileAtomically(tag,
                               "Signature: 8a477f597d28d172789f06886806bc55\n"
                               "# This file is a cache directory tag created by shaderport.\n",
                               {.sync_to_disk = false, .user_named_target = false});
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
  // A FIFO or device planted under the entry's name is a miss, not a hang.
  return file_io::ReadRegularFile(EntryPath(key), limits::kMaxCacheEntryBytes).bytes;
}

bool ResultCache::Store(const CacheKey& key, std::string_view bytes) const {
  const fs::path target = EntryPath(key);
  std::error_code error;
  if (!fs::is_directory(target.parent_path(), error)) {
    fs::create_directories(target.parent_path(), error);
    if (error) return false;
    TagCacheDirectory(directory_);
  }
  // Not synced to disk: a torn entry fails its checksum and is a miss
  // (DecodeCacheEntry), and a flush per entry would slow every cold run.
  return file_io::WriteFileAtomically(target, bytes,
                                      {.sync_to_disk = false, .user_named_target = false})
      .empty();
}

void ResultCache::Prune(const CacheLimits& limits, fs::file_time_type now) const {
  std::error_code error;
  const fs::path stamp = entries_ / kPruneStamp;
  const fs::file_time_type last = fs::last_write_time(stamp, error);
  if (!error && now - last < limits.prune_interval) return;
  if (!fs::is_directory(entries_, error)) return;
  // Claim this prune before the walk, so concurrent runs skip it.
  file_io::WriteFileAtomically(stamp, "", {.sync_to_disk = false, .user_named_target = false});
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
    const std::string name = it->path().filename().string();
    const bool temporary =
        name.starts_with(kTemporaryPrefix) || file_io::IsAtomicWriteTemporary(name);
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
