#include "driver/check_cache.h"

#include <glslang/build_info.h>

#include "driver/cache_entry.h"
#include "driver/read_input.h"

namespace shaderport::driver {
namespace {

template <typename Enum>
uint64_t Value(const std::optional<Enum>& value) {
  return value ? static_cast<uint64_t>(*value) + 1 : 0;
}

// Everything of the run that changes a file's findings.
CacheKey RunKey(const CheckOptions& options) {
  KeyHasher hasher;
  hasher.Add(kCacheEntryVersion)
      .Add(options.tool_identity)
      .Add(std::string_view(GLSLANG_VERSION_FLAVOR))
      .Add(uint64_t{GLSLANG_VERSION_MAJOR} << 32 | GLSLANG_VERSION_MINOR << 16 |
           GLSLANG_VERSION_PATCH)
      .Add(Value(options.dialect))
      .Add(Value(options.stage))
      .Add(Value(options.target));
  // Only when given, so that entries written before the option existed still match.
  if (!options.enabled_extensions.EnablesAll()) {
    hasher.Add(std::string_view("extensions=")).Add(options.enabled_extensions.Describe());
  }
  for (size_t i = 0; i < options.channels.size(); ++i) {
    // Hashed as a kind (2D when not given) and a given flag, as before the flag and
    // the kind were one optional: cache entries written then still match.
    hasher.Add(static_cast<uint64_t>(options.channels[i].value_or(model::ChannelKind::k2D)))
        .Add(uint64_t{options.channels[i].has_value() ? 1u : 0u});
  }
  // A --dialect harness: what of it decides how a file is composed.
  if (const model::HarnessDialect* harness = options.harness) {
    hasher.Add(harness->name).Add(harness->prelude).Add(static_cast<uint64_t>(harness->declare));
    for (const std::string& define : harness->defines) hasher.Add(define);
    for (const model::ProvidedVariable& provided : harness->provides) {
      hasher.Add(provided.name).Add(provided.type).Add(static_cast<uint64_t>(provided.storage));
      hasher.Add(provided.precision).Add(static_cast<uint64_t>(provided.channel + 1));
    }
  }
  return hasher.Finish();
}

// The config as parsed: what it says, not how it is written.
CacheKey ConfigKey(const Config* config) {
  KeyHasher hasher;
  if (config == nullptr) return hasher.Add(uint64_t{0}).Finish();
  hasher.Add(config->directory.string()).Add(static_cast<uint64_t>(config->fail_on));
  hasher.Add(config->rules.size());
  for (const RuleSetting& rule : config->rules) {
    hasher.Add(rule.pattern).Add(static_cast<uint64_t>(rule.level));
  }
  hasher.Add(config->include.size());
  for (const std::string& glob : config->include) hasher.Add(glob);
  hasher.Add(config->exclude.size());
  for (const std::string& glob : config->exclude) hasher.Add(glob);
  hasher.Add(config->files.size());
  for (const FileOverride& file : config->files) {
    hasher.Add(file.glob).Add(Value(file.dialect)).Add(Value(file.stage)).Add(Value(file.target));
  }
  return hasher.Finish();
}

CacheKey CommonKey(const SourceFile* common) {
  KeyHasher hasher;
  if (common == nullptr) return hasher.Add(uint64_t{0}).Finish();
  return hasher.Add(uint64_t{1}).Add(common->Name()).Add(common->Text()).Finish();
}

CacheKey FileKey(const CacheKey& job_key, const FileJob& job, std::string_view text) {
  return KeyHasher()
      .Add(job_key)
      .Add(job.path.string())
      .Add(job.absolute_path.string())
      .Add(text)
      .Finish();
}

}  // namespace

CheckCache::CheckCache(const CheckOptions& options, const std::vector<FileJob>& jobs)
    : options_(options), jobs_(jobs), store_(*options.cache_directory) {
  const CacheKey run = RunKey(options);
  // Configs and Common files are shared by many jobs: each is hashed once.
  std::map<const Config*, CacheKey> configs;
  std::map<const SourceFile*, CacheKey> commons;
  job_keys_.reserve(jobs.size());
  for (const FileJob& job : jobs) {
    auto config = configs.find(job.config);
    if (config == configs.end()) config = configs.emplace(job.config, ConfigKey(job.config)).first;
    auto common = commons.find(job.common);
    if (common == commons.end()) common = commons.emplace(job.common, CommonKey(job.common)).first;
    job_keys_.push_back(KeyHasher()
                            .Add(run)
                            .Add(config->second)
                            .Add(common->second)
                            .Add(uint64_t{job.common_checked_separately})
                            .Finish());
  }
}

FileReport CheckCache::Check(size_t index, SourceManager& sources) {
  const FileJob& job = jobs_[index];
  // Passes of projects are not cached: the key knows nothing of their tab and inputs.
  if (job.source != nullptr || job.pass) return CheckFile(job, options_, sources);
  InputText input = ReadInputFile(job.path);
  // A file that cannot be read is reported by CheckFile, as without a cache.
  if (!input.text) return CheckFile(job, options_, sources);
  const CacheKey key = FileKey(job_keys_[index], job, *input.text);
  if (std::optional<std::string> bytes = store_.Load(key)) {
    std::optional<CacheEntry> entry = DecodeCacheEntry(*bytes, key);
    if (entry && EntryFits(*entry, job.common)) {
      ++hits_;
      return RestoreReport(std::move(*entry), job.path.string(), std::move(*input.text), job.common,
                           sources);
    }
  }
  FileReport report = CheckFile(job, options_, sources);
  // Stored only when CheckFile saw the text that was hashed (the file may have
  // changed in between).
  if (report.file != nullptr && report.file->Text() == *input.text) {
    if (std::optional<std::string> bytes = EncodeCacheEntry(report, job.common, sources, key)) {
      if (store_.Store(key, *bytes)) stored_ = true;
    }
  }
  return report;
}

void CheckCache::Finish(const CacheLimits& limits) {
  if (stored_) store_.Prune(limits);
}

}  // namespace shaderport::driver
