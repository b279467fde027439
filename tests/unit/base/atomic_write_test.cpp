// WriteFileAtomically through both temporaries (anonymous O_TMPFILE and the
// named fallback), the removal of stale temporaries, and symlink edge cases.
#include "base/file_io/atomic_write.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "golden.h"

namespace shaderport::file_io {
namespace {

namespace fs = std::filesystem;
using shaderport::testing::ReadWholeFile;

// A fresh directory per test: stale temporaries are looked for once per directory.
class AtomicWrite : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(test->name()) + "-" + std::to_string(::getpid());
    std::replace(name.begin(), name.end(), '/', '-');
    dir_ = fs::temp_directory_path() / ("shaderport-atomic-" + name);
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  AtomicWriteOptions Options() const { return {.anonymous_temporary = GetParam()}; }
  std::vector<std::string> Entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }
  void Put(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name, std::ios::binary) << text;
  }
  fs::path dir_;
};

TEST_P(AtomicWrite, ReplacesKeepingTheModeAndLeavesNothingElse) {
  Put("a.glsl", "old");
  ASSERT_EQ(::chmod((dir_ / "a.glsl").c_str(), 0604), 0);
  ASSERT_EQ(WriteFileAtomically(dir_ / "a.glsl", "new text", Options()), "");
  EXPECT_EQ(ReadWholeFile(dir_ / "a.glsl"), "new text");
  EXPECT_EQ(fs::status(dir_ / "a.glsl").permissions(), static_cast<fs::perms>(0604));
  EXPECT_EQ(Entries(), std::vector<std::string>{"a.glsl"});
}

TEST_P(AtomicWrite, NewFileGetsTheUmaskMode) {
  const mode_t previous = ::umask(027);
  const std::string error = WriteFileAtomically(dir_ / "new.glsl", "text", Options());
  ::umask(previous);
  ASSERT_EQ(error, "");
  EXPECT_EQ(ReadWholeFile(dir_ / "new.glsl"), "text");
  EXPECT_EQ(fs::status(dir_ / "new.glsl").permissions(), static_cast<fs::perms>(0640));
  EXPECT_EQ(Entries(), std::vector<std::string>{"new.glsl"});
}

TEST_P(AtomicWrite, RemovesOnlyStaleTemporariesOfItsOwnPattern) {
  const std::string stale = ".a.glsl.shaderport-123-abcDE9.tmp";
  const std::string young = ".b.glsl.shaderport-456-XYZxyz.tmp";
  const std::string foreign = ".a.glsl.shaderport-notes.tmp";
  for (const std::string& name : {stale, young, foreign}) Put(name, "x");
  const std::time_t hour_ago = std::time(nullptr) - 3600;
  const timespec times[2] = {{hour_ago, 0}, {hour_ago, 0}};
  ASSERT_EQ(::utimensat(AT_FDCWD, (dir_ / stale).c_str(), times, 0), 0);
  ASSERT_EQ(::utimensat(AT_FDCWD, (dir_ / foreign).c_str(), times, 0), 0);
  ASSERT_EQ(WriteFileAtomically(dir_ / "a.glsl", "text", Options()), "");
  EXPECT_EQ(Entries(), (std::vector<std::string>{foreign, young, "a.glsl"}));
}

TEST_P(AtomicWrite, WritesThroughASymlinkChainToItsTarget) {
  Put("real.glsl", "old");
  fs::create_directories(dir_ / "sub");
  fs::create_symlink("../real.glsl", dir_ / "sub/one.glsl");
  fs::create_symlink(dir_ / "sub/one.glsl", dir_ / "two.glsl");  // absolute
  ASSERT_EQ(WriteFileAtomically(dir_ / "two.glsl", "new", Options()), "");
  EXPECT_EQ(ReadWholeFile(dir_ / "real.glsl"), "new");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir_ / "two.glsl")));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir_ / "sub/one.glsl")));
}

TEST_P(AtomicWrite, DanglingSymlinkCreatesItsTarget) {
  fs::create_symlink("made.glsl", dir_ / "link.glsl");
  ASSERT_EQ(WriteFileAtomically(dir_ / "link.glsl", "text", Options()), "");
  EXPECT_EQ(ReadWholeFile(dir_ / "made.glsl"), "text");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir_ / "link.glsl")));
}

TEST_P(AtomicWrite, RefusesLoopsAndDirectories) {
  fs::create_symlink("loop.glsl", dir_ / "loop.glsl");
  EXPECT_NE(WriteFileAtomically(dir_ / "loop.glsl", "x", Options())
                .find("Too many levels of symbolic links"),
            std::string::npos);
  fs::create_directories(dir_ / "d.glsl");
  EXPECT_NE(WriteFileAtomically(dir_ / "d.glsl", "x", Options()).find("not a regular file"),
            std::string::npos);
  EXPECT_EQ(Entries(), (std::vector<std::string>{"d.glsl", "loop.glsl"}));
}

INSTANTIATE_TEST_SUITE_P(Temporaries, AtomicWrite, ::testing::Values(true, false),
                         [](const auto& test) { return test.param ? "Anonymous" : "Named"; });

TEST(AtomicWriteTemporaryName, MatchesOnlyItsOwnPattern) {
  EXPECT_TRUE(IsAtomicWriteTemporary(".a.glsl.shaderport-123-abcDE9.tmp"));
  EXPECT_TRUE(IsAtomicWriteTemporary("..hidden.shaderport-1-aaaaaa.tmp"));
  EXPECT_FALSE(IsAtomicWriteTemporary("a.glsl.shaderport-123-abcDE9.tmp"));  // no leading dot
  EXPECT_FALSE(IsAtomicWriteTemporary("..shaderport-123-abcDE9.tmp"));       // no target name
  EXPECT_FALSE(IsAtomicWriteTemporary(".a.glsl.shaderport--abcDE9.tmp"));    // no pid
  EXPECT_FALSE(IsAtomicWriteTemporary(".a.glsl.shaderport-12x-abcDE9.tmp"));
  EXPECT_FALSE(IsAtomicWriteTemporary(".a.glsl.shaderport-123-abcDE.tmp"));
  EXPECT_FALSE(IsAtomicWriteTemporary(".a.glsl.shaderport-123-abc_E9.tmp"));
  EXPECT_FALSE(IsAtomicWriteTemporary(".a.glsl.shaderport-123-abcDE9"));
  EXPECT_FALSE(IsAtomicWriteTemporary(".a.glsl.shaderport-AbC123"));  // the old mkstemp name
}

}  // namespace
}  // namespace shaderport::file_io
