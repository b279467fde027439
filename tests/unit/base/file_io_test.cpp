// The bounded reader, file identity and the escaping of control characters, on
// real files: FIFOs, devices, links.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "base/file_io/read_regular_file.h"
#include "base/file_io/same_file.h"
#include "base/printable.h"

namespace shaderport::file_io {
namespace {

namespace fs = std::filesystem;

class FileIoTest : public ::testing::Test {
 protected:
  FileIoTest() : dir_(fs::temp_directory_path() / ("file-io-" + std::to_string(::getpid()))) {
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  ~FileIoTest() override { fs::remove_all(dir_); }
  fs::path Write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  fs::path dir_;
};

TEST_F(FileIoTest, ReadsRegularFilesWithinTheCap) {
  const fs::path file = Write("a.txt", "hello");
  const ReadResult read = ReadRegularFile(file, 5);
  ASSERT_TRUE(read.bytes);
  EXPECT_EQ(*read.bytes, "hello");
  const ReadResult large = ReadRegularFile(file, 4);
  EXPECT_FALSE(large.bytes);
  EXPECT_EQ(large.failure, ReadFailure::kTooLarge);
  EXPECT_EQ(large.size, 5u);
  EXPECT_EQ(ReadRegularFile(dir_ / "missing", 10).failure, ReadFailure::kCannotOpen);
}

TEST_F(FileIoTest, FifosDevicesAndDirectoriesAreRefusedWithoutBlocking) {
  ASSERT_EQ(::mkfifo((dir_ / "fifo").c_str(), 0644), 0);
  for (const fs::path& path : {dir_ / "fifo", fs::path("/dev/zero"), dir_}) {
    const ReadResult read = ReadRegularFile(path, 1 << 20);
    EXPECT_FALSE(read.bytes) << path;
    EXPECT_EQ(read.failure, ReadFailure::kNotRegular) << path;
    EXPECT_EQ(read.message.rfind("not a regular file: ", 0), 0u) << read.message;
  }
  EXPECT_EQ(ReadRegularFileHead(dir_ / "fifo", 10), "");
  EXPECT_EQ(ReadRegularFileHead(Write("b.txt", "0123456789abc"), 10), "0123456789");
}

TEST_F(FileIoTest, IdentityFollowsLinksAndSpellings) {
  const fs::path file = Write("s.frag", "x");
  fs::create_hard_link(file, dir_ / "hard.frag");
  fs::create_symlink(file, dir_ / "soft.frag");
  const std::vector<fs::path> inputs{file};
  for (const fs::path& same : {dir_ / "hard.frag", dir_ / "soft.frag", dir_ / "." / "s.frag"}) {
    EXPECT_EQ(InputReplacedBy(same, inputs), file) << same;
  }
  EXPECT_EQ(InputReplacedBy(Write("other.frag", "x"), inputs), std::nullopt);
  EXPECT_EQ(InputReplacedBy(dir_ / "new.frag", inputs), std::nullopt);  // not there yet
}

TEST(PrintableTest, EscapesControlCharactersOnly) {
  EXPECT_EQ(EscapeControlCharacters("a\nb\tc\x1b[2J\x7f"), "a\\nb\\tc\\x1b[2J\\x7f");
  EXPECT_EQ(EscapeControlCharacters("\xC2\x9B"
                                    "31m caf\xC3\xA9"),
            "\\u009b31m caf\xC3\xA9");
  EXPECT_EQ(EscapeControlCharacters("\xC2"), "\xC2");  // a lone lead byte is kept
  EXPECT_EQ(OneLinePrintable("two\nlines\r\x07"), "two lines \\x07");
}

}  // namespace
}  // namespace shaderport::file_io
