#include "driver/shard.h"

#include <charconv>
#include <numeric>

namespace shaderport::driver {
namespace {

std::optional<unsigned> ParseCount(std::string_view text) {
  unsigned value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

// Union-find over file indices: every group ends up with one representative.
class Groups {
 public:
  explicit Groups(size_t size) : parent_(size) { std::iota(parent_.begin(), parent_.end(), 0); }
  size_t Find(size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void Join(size_t a, size_t b) {
    a = Find(a);
    b = Find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<size_t> parent_;
};

}  // namespace

std::optional<ShardSpec> ParseShardSpec(std::string_view text, std::string& error) {
  const size_t slash = text.find('/');
  const std::optional<unsigned> index =
      slash == std::string_view::npos ? std::nullopt : ParseCount(text.substr(0, slash));
  const std::optional<unsigned> count =
      slash == std::string_view::npos ? std::nullopt : ParseCount(text.substr(slash + 1));
  if (!index || !count) {
    error = "bad --shard '" + std::string(text) + "' (expected K/N, e.g. 1/4)";
    return std::nullopt;
  }
  if (*count == 0 || *index == 0 || *index > *count) {
    error = "bad --shard '" + std::string(text) + "': K must be between 1 and N, and N at least 1";
    return std::nullopt;
  }
  return ShardSpec{*index, *count};
}

std::string ShardName(const std::filesystem::path& file, const std::filesystem::path& base) {
  const std::filesystem::path absolute =
      (file.is_absolute() ? file : base / file).lexically_normal();
  const std::filesystem::path relative = absolute.lexically_relative(base);
  return (relative.empty() ? absolute : relative).generic_string();
}

uint64_t StableHash(std::string_view text) {
  uint64_t hash = 14695981039346656037ull;
  for (char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ull;
  }
  return hash;
}

std::vector<bool> SelectShard(const std::vector<std::string>& names,
                              const std::vector<std::pair<size_t, size_t>>& together,
                              const ShardSpec& shard) {
  Groups groups(names.size());
  for (const auto& [a, b] : together) {
    if (a < names.size() && b < names.size()) groups.Join(a, b);
  }
  // The group's smallest name decides: independent of input order and of files
  // outside the group.
  std::vector<const std::string*> group_name(names.size(), nullptr);
  for (size_t i = 0; i < names.size(); ++i) {
    const std::string*& smallest = group_name[groups.Find(i)];
    if (smallest == nullptr || names[i] < *smallest) smallest = &names[i];
  }
  std::vector<bool> selected(names.size());
  for (size_t i = 0; i < names.size(); ++i) {
    selected[i] = StableHash(*group_name[groups.Find(i)]) % shard.count == shard.index - 1;
  }
  return selected;
}

}  // namespace shaderport::driver
