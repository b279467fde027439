// The result cache as `check` uses it: a file's findings are keyed on its text,
// its path, its ShaderToy Common code, the .shaderport.toml that governs it, the
// options that change findings and the tool's identity (shaderport's version and
// build, glslang's version). Link findings are not cached: they are recomputed
// from both stages (our front end only, no glslang). With --render nothing is
// cached (a picture depends on Mesa and on time limits).
#pragma once

#include <atomic>
#include <map>
#include <vector>

#include "driver/check_file.h"
#include "driver/result_cache.h"

namespace shaderport::driver {

class CheckCache {
 public:
  // `jobs` must outlive the cache; options.cache_directory must be set.
  CheckCache(const CheckOptions& options, const std::vector<FileJob>& jobs);

  // CheckFile(jobs[index]) from the cache, or checked and stored. Thread-safe.
  FileReport Check(size_t index, SourceManager& sources);

  // Prunes the cache when this run wrote to it (see CacheLimits).
  void Finish(const CacheLimits& limits = {});

  size_t Hits() const { return hits_; }

 private:
  const CheckOptions& options_;
  const std::vector<FileJob>& jobs_;
  ResultCache store_;
  std::vector<CacheKey> job_keys_;  // per job: the run, its config and its Common
  std::atomic<size_t> hits_{0};
  std::atomic<bool> stored_{false};
};

}  // namespace shaderport::driver
