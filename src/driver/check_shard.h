// `check --shard K/N` on the run's jobs: the files of other shards are dropped,
// but linked programs and the passes of a directory with a common.glsl (with
// that file) stay together, because each needs the others' results.
#pragma once

#include <filesystem>
#include <vector>

#include "driver/check_file.h"
#include "driver/shard.h"

namespace shaderport::driver {

// Keeps the jobs of `shard`, in their order. Names are taken relative to `base`
// (the current directory).
void KeepShard(std::vector<FileJob>& jobs, const CheckOptions& options, const ShardSpec& shard,
               const std::filesystem::path& base);

}  // namespace shaderport::driver
