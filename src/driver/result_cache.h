// The result cache on disk: one file per entry, named by its key, under
// DIR/v<format>/<first two hex digits>/. Writers write a temporary file in the
// same directory and rename it into place, so concurrent runs never see a
// partial entry; readers treat a missing or unreadable entry as a miss.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "driver/cache_key.h"

namespace shaderport::driver {

// What bounds the cache. Entries are pruned by the age of their last write and
// then, oldest first, down to three quarters of the size cap.
struct CacheLimits {
  std::chrono::hours max_age{24 * 30};
  uintmax_t max_bytes = 256u << 20;
  std::chrono::hours prune_interval{24};  // a run prunes only when the last prune is older
};

// $XDG_CACHE_HOME/shaderport when that is an absolute path, else ~/.cache/shaderport;
// nullopt when neither variable helps (the cache is then off).
std::optional<std::filesystem::path> DefaultCacheDirectory(const char* xdg_cache_home,
                                                           const char* home);

class ResultCache {
 public:
  explicit ResultCache(std::filesystem::path directory);

  // The entry's bytes, or nullopt when there is none (or it cannot be read).
  std::optional<std::string> Load(const CacheKey& key) const;
  // Atomically replaces the entry; false (and nothing changed) when it cannot.
  bool Store(const CacheKey& key, std::string_view bytes) const;
  // Applies `limits` when the last prune is older than limits.prune_interval.
  void Prune(const CacheLimits& limits, std::filesystem::file_time_type now =
                                            std::filesystem::file_time_type::clock::now()) const;

  std::filesystem::path EntryPath(const CacheKey& key) const;
  const std::filesystem::path& Directory() const { return directory_; }

 private:
  std::filesystem::path directory_;  // the user's cache directory
  std::filesystem::path entries_;    // directory_ / "v<format>"
};

}  // namespace shaderport::driver
