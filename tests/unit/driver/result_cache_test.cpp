#include "driver/result_cache.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;
using std::chrono::hours;

class ResultCacheTest : public ::testing::Test {
 protected:
  ResultCacheTest()
      : directory_(fs::temp_directory_path() /
                   ("shaderport-cache-test-" + std::to_string(::getpid()) + "-" +
                    ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
    fs::remove_all(directory_);
  }
  ~ResultCacheTest() override { fs::remove_all(directory_); }

  static CacheKey Key(uint64_t n) { return KeyHasher().Add(n).Finish(); }

  fs::path directory_;
};

TEST_F(ResultCacheTest, StoresAndLoadsEntries) {
  const ResultCache cache(directory_);
  EXPECT_FALSE(cache.Load(Key(1)));
  ASSERT_TRUE(cache.Store(Key(1), "one"));
  ASSERT_TRUE(cache.Store(Key(2), std::string("t\0o", 3)));
  EXPECT_EQ(cache.Load(Key(1)), "one");
  EXPECT_EQ(cache.Load(Key(2)), std::string("t\0o", 3));
  ASSERT_TRUE(cache.Store(Key(1), "replaced"));
  EXPECT_EQ(cache.Load(Key(1)), "replaced");
  EXPECT_TRUE(fs::exists(directory_ / "CACHEDIR.TAG"));
  // No temporary file is left behind.
  for (const auto& entry : fs::recursive_directory_iterator(directory_)) {
    EXPECT_FALSE(entry.path().filename().string().starts_with(".tmp-")) << entry.path();
  }
}

TEST_F(ResultCacheTest, AnUnwritableDirectoryIsNoCache) {
  fs::create_directories(directory_.parent_path());
  std::ofstream(directory_) << "a file, not a directory";
  const ResultCache cache(directory_);
  EXPECT_FALSE(cache.Store(Key(1), "one"));
  EXPECT_FALSE(cache.Load(Key(1)));
  fs::remove(directory_);
}

TEST_F(ResultCacheTest, PruneDropsOldEntriesAndDeadTemporaries) {
  const ResultCache cache(directory_);
  ASSERT_TRUE(cache.Store(Key(1), "old"));
  ASSERT_TRUE(cache.Store(Key(2), "new"));
  const fs::path temporary = cache.EntryPath(Key(2)).parent_path() / ".tmp-dead";
  std::ofstream(temporary) << "partial";
  const auto now = fs::file_time_type::clock::now();
  fs::last_write_time(cache.EntryPath(Key(1)), now - hours(24 * 31));
  fs::last_write_time(temporary, now - hours(2));
  cache.Prune(CacheLimits{}, now);
  EXPECT_FALSE(cache.Load(Key(1)));
  EXPECT_EQ(cache.Load(Key(2)), "new");
  EXPECT_FALSE(fs::exists(temporary));
}

TEST_F(ResultCacheTest, PruneKeepsTheNewestEntriesUnderTheSizeCap) {
  const ResultCache cache(directory_);
  const auto now = fs::file_time_type::clock::now();
  for (uint64_t i = 0; i < 10; ++i) {
    ASSERT_TRUE(cache.Store(Key(i), std::string(100, 'x')));
    fs::last_write_time(cache.EntryPath(Key(i)), now - hours(10 - i));
  }
  CacheLimits limits;
  limits.max_bytes = 500;  // 1,000 bytes stored: down to 375, the 3 newest
  cache.Prune(limits, now);
  for (uint64_t i = 0; i < 10; ++i) EXPECT_EQ(cache.Load(Key(i)).has_value(), i >= 7) << i;
}

TEST_F(ResultCacheTest, PruneRunsOncePerInterval) {
  const ResultCache cache(directory_);
  ASSERT_TRUE(cache.Store(Key(1), "x"));
  const auto now = fs::file_time_type::clock::now();
  cache.Prune(CacheLimits{}, now);
  fs::last_write_time(cache.EntryPath(Key(1)), now - hours(24 * 40));
  cache.Prune(CacheLimits{}, now + hours(1));  // within the day: not pruned again
  EXPECT_TRUE(cache.Load(Key(1)));
  cache.Prune(CacheLimits{}, now + hours(25));
  EXPECT_FALSE(cache.Load(Key(1)));
}

TEST(DefaultCacheDirectoryTest, FollowsXdgThenHome) {
  EXPECT_EQ(DefaultCacheDirectory("/xdg", "/home/u"), fs::path("/xdg/shaderport"));
  EXPECT_EQ(DefaultCacheDirectory(nullptr, "/home/u"), fs::path("/home/u/.cache/shaderport"));
  // The XDG spec ignores relative values.
  EXPECT_EQ(DefaultCacheDirectory("relative", "/home/u"), fs::path("/home/u/.cache/shaderport"));
  EXPECT_EQ(DefaultCacheDirectory(nullptr, nullptr), std::nullopt);
  EXPECT_EQ(DefaultCacheDirectory("", ""), std::nullopt);
}

}  // namespace
}  // namespace shaderport::driver
