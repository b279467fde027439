// `check --shard K/N`: a stable 1/N of the input files, so that N CI jobs can
// share a large repository and `shaderport merge` can join what they report.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace shaderport::driver {

struct ShardSpec {
  unsigned index = 1;  // 1-based, as pytest-shard and Jest count
  unsigned count = 1;
  friend bool operator==(const ShardSpec&, const ShardSpec&) = default;
};

// "K/N" with 1 <= K <= N; nullopt and a message in `error` for anything else.
std::optional<ShardSpec> ParseShardSpec(std::string_view text, std::string& error);

// The name a file is hashed by: its path relative to `base` with '/' separators
// (the absolute path when it has no relative form), so the same checkout gives
// the same shards on every machine.
std::string ShardName(const std::filesystem::path& file, const std::filesystem::path& base);

// 64-bit FNV-1a: stable across runs, platforms and standard libraries.
uint64_t StableHash(std::string_view text);

// Which files belong to `shard`. Files joined by `together` (index pairs: linked
// programs, ShaderToy passes and their Common) form one group that lands on one
// shard, chosen by the hash of the group's smallest name; so adding a file moves
// no other group.
std::vector<bool> SelectShard(const std::vector<std::string>& names,
                              const std::vector<std::pair<size_t, size_t>>& together,
                              const ShardSpec& shard);

}  // namespace shaderport::driver
