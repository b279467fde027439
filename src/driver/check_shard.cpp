#include "driver/check_shard.h"

#include <map>
#include <string>

#include "driver/check_link.h"

namespace shaderport::driver {

namespace fs = std::filesystem;

void KeepShard(std::vector<FileJob>& jobs, const CheckOptions& options, const ShardSpec& shard,
               const fs::path& base) {
  std::vector<std::string> names;
  names.reserve(jobs.size());
  for (const FileJob& job : jobs) names.push_back(ShardName(job.path, base));

  std::vector<std::pair<size_t, size_t>> together = FindPrograms(jobs, options);
  // A directory's common.glsl goes with its passes (a --common file is shared by
  // every pass of the run: those are spread, and each shard reads the file).
  if (!options.common) {
    std::map<std::string, size_t> first_of_directory;
    for (size_t i = 0; i < jobs.size(); ++i) {
      const bool in_common_directory =
          jobs[i].common != nullptr || jobs[i].path.filename() == "common.glsl";
      if (!in_common_directory) continue;
      const std::string directory = ShardName(jobs[i].path.parent_path(), base);
      const auto [first, inserted] = first_of_directory.emplace(directory, i);
      if (!inserted) together.emplace_back(first->second, i);
    }
  }
  const std::vector<bool> keep = SelectShard(names, together, shard);
  std::vector<FileJob> kept;
  for (size_t i = 0; i < jobs.size(); ++i) {
    if (keep[i]) kept.push_back(std::move(jobs[i]));
  }
  jobs = std::move(kept);
}

}  // namespace shaderport::driver
