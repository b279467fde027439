#include "driver/shard.h"

#include <gtest/gtest.h>

#include <set>

namespace shaderport::driver {
namespace {

TEST(ShardSpecTest, ParsesKOfN) {
  std::string error;
  EXPECT_EQ(ParseShardSpec("1/4", error), (ShardSpec{1, 4}));
  EXPECT_EQ(ParseShardSpec("4/4", error), (ShardSpec{4, 4}));
  EXPECT_EQ(ParseShardSpec("1/1", error), (ShardSpec{1, 1}));
}

TEST(ShardSpecTest, RejectsBadSpecsWithAMessage) {
  for (const char* bad : {"", "1", "0/4", "5/4", "1/0", "a/b", "1/4x", "-1/4", "1//4", "/4", "1/",
                          " 1/4", "99999999999/4"}) {
    std::string error;
    EXPECT_FALSE(ParseShardSpec(bad, error)) << bad;
    EXPECT_NE(error.find("--shard"), std::string::npos) << bad;
  }
}

TEST(ShardNameTest, IsRelativeToTheBaseWithForwardSlashes) {
  EXPECT_EQ(ShardName("a/b.frag", "/repo"), "a/b.frag");
  EXPECT_EQ(ShardName("./a/../a/b.frag", "/repo"), "a/b.frag");
  EXPECT_EQ(ShardName("/repo/a/b.frag", "/repo"), "a/b.frag");
  EXPECT_EQ(ShardName("/elsewhere/b.frag", "/repo"), "../elsewhere/b.frag");
}

TEST(StableHashTest, IsFnv1a) {
  // Fixed values: a shard assignment must not change between builds or machines.
  EXPECT_EQ(StableHash(""), 14695981039346656037ull);
  EXPECT_EQ(StableHash("a"), 0xaf63dc4c8601ec8cull);
}

std::vector<std::string> Names(size_t count) {
  std::vector<std::string> names;
  for (size_t i = 0; i < count; ++i)
    names.push_back("dir" + std::to_string(i % 7) + "/" + std::to_string(i) + ".frag");
  return names;
}

TEST(SelectShardTest, EveryFileIsInExactlyOneShard) {
  const std::vector<std::string> names = Names(200);
  std::vector<int> seen(names.size(), 0);
  for (unsigned k = 1; k <= 4; ++k) {
    const std::vector<bool> selected = SelectShard(names, {}, {k, 4});
    size_t count = 0;
    for (size_t i = 0; i < names.size(); ++i) {
      seen[i] += selected[i] ? 1 : 0;
      count += selected[i] ? 1 : 0;
    }
    // Roughly a quarter each (200 files: far from 0 or 200).
    EXPECT_GT(count, 25u);
    EXPECT_LT(count, 75u);
  }
  for (int times : seen) EXPECT_EQ(times, 1);
}

TEST(SelectShardTest, OneShardTakesEverything) {
  const std::vector<bool> selected = SelectShard(Names(20), {}, {1, 1});
  EXPECT_EQ(std::count(selected.begin(), selected.end(), true), 20);
}

TEST(SelectShardTest, AddingAFileMovesNoOtherFile) {
  std::vector<std::string> names = Names(100);
  const std::vector<bool> before = SelectShard(names, {}, {2, 3});
  names.insert(names.begin() + 10, "new/file.frag");
  const std::vector<bool> after = SelectShard(names, {}, {2, 3});
  for (size_t i = 0; i < 100; ++i) EXPECT_EQ(before[i], after[i < 10 ? i : i + 1]) << i;
}

TEST(SelectShardTest, GroupsStayTogether) {
  const std::vector<std::string> names = Names(60);
  // Three chains of files that must share a shard.
  const std::vector<std::pair<size_t, size_t>> together = {{0, 1}, {1, 2}, {10, 50}, {30, 31}};
  for (unsigned k = 1; k <= 5; ++k) {
    const std::vector<bool> selected = SelectShard(names, together, {k, 5});
    EXPECT_EQ(selected[0], selected[1]);
    EXPECT_EQ(selected[1], selected[2]);
    EXPECT_EQ(selected[10], selected[50]);
    EXPECT_EQ(selected[30], selected[31]);
  }
}

TEST(SelectShardTest, DoesNotDependOnInputOrder) {
  std::vector<std::string> names = Names(50);
  const std::vector<bool> forward = SelectShard(names, {{3, 4}}, {1, 3});
  std::vector<std::string> reversed(names.rbegin(), names.rend());
  const std::vector<bool> backward = SelectShard(reversed, {{45, 46}}, {1, 3});
  for (size_t i = 0; i < names.size(); ++i) EXPECT_EQ(forward[i], backward[names.size() - 1 - i]);
}

}  // namespace
}  // namespace shaderport::driver
