// The result cache of `shaderport check` through the real binary: a warm run
// prints what a cold one does, byte for byte, and a broken cache is never trusted.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "cli_test_util.h"

namespace shaderport::testing {
namespace {

namespace fs = std::filesystem;

class CacheCliTest : public ::testing::Test {
 protected:
  CacheCliTest()
      : root_(fs::temp_directory_path() /
              ("shaderport-cache-cli-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  ~CacheCliTest() override { fs::remove_all(root_); }

  fs::path Cache() const { return root_ / "cache"; }
  std::string CacheOption() const { return "--cache-dir '" + Cache().string() + "' "; }

  std::vector<fs::path> Entries() const {
    std::vector<fs::path> entries;
    if (!fs::exists(Cache())) return entries;
    for (const auto& entry : fs::recursive_directory_iterator(Cache())) {
      const std::string name = entry.path().filename().string();
      if (entry.is_regular_file() && name.size() == 32) entries.push_back(entry.path());
    }
    std::sort(entries.begin(), entries.end());
    return entries;
  }

  void Write(const fs::path& file, const std::string& text) const {
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
  }

  fs::path root_;
};

TEST_F(CacheCliTest, WarmRunsPrintWhatColdRunsPrint) {
  for (const std::string format : {"text", "json", "sarif"}) {
    const std::string args = "check --format " + format + " corpus";
    const CommandResult plain = RunShaderport(args + " --no-cache", SourceDir());
    const CommandResult cold = RunShaderport(args + " " + CacheOption(), SourceDir());
    const CommandResult warm = RunShaderport(args + " " + CacheOption(), SourceDir());
    EXPECT_EQ(plain.exit_code, 1) << plain.err;
    EXPECT_FALSE(plain.out.empty());
    EXPECT_EQ(cold.out, plain.out) << format;
    EXPECT_EQ(warm.out, plain.out) << format;
    EXPECT_EQ(warm.exit_code, plain.exit_code);
    EXPECT_EQ(warm.err, plain.err);
  }
  // One entry per corpus file, whatever the format.
  size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(SourceDir() / "corpus")) {
    files += entry.path().extension() == ".glsl" || entry.path().extension() == ".frag" ||
             entry.path().extension() == ".vert";
  }
  EXPECT_EQ(Entries().size(), files);
}

TEST_F(CacheCliTest, NoCacheWritesNothing) {
  RunShaderport("check --no-cache " + CacheOption() + "corpus", SourceDir());
  EXPECT_FALSE(fs::exists(Cache()));
}

TEST_F(CacheCliTest, TheDefaultDirectoryFollowsXdgCacheHome) {
  const CommandResult run = RunShaderport("check corpus/ao", SourceDir(),
                                          "NO_COLOR=1 XDG_CACHE_HOME='" + root_.string() + "'");
  EXPECT_EQ(run.err, "");
  EXPECT_TRUE(fs::exists(root_ / "shaderport" / "CACHEDIR.TAG"));
}

TEST_F(CacheCliTest, BrokenEntriesAreIgnoredAndRewritten) {
  const std::string args = "check --format json " + CacheOption() + "corpus";
  const CommandResult cold = RunShaderport(args, SourceDir());
  const std::vector<fs::path> entries = Entries();
  ASSERT_GT(entries.size(), 4u);
  std::vector<std::string> originals;
  for (const fs::path& entry : entries) originals.push_back(ReadWholeFile(entry));
  // Truncated, a flipped byte, someone else's file, empty, and an entry of
  // another file under this file's name.
  for (size_t i = 0; i < entries.size(); ++i) {
    std::string broken = originals[i];
    switch (i % 5) {
      case 0:
        broken.resize(broken.size() / 2);
        break;
      case 1:
        broken[broken.size() / 2] = static_cast<char>(broken[broken.size() / 2] ^ 1);
        break;
      case 2:
        broken = "{\"not\": \"a cache entry\"}\n";
        break;
      case 3:
        broken.clear();
        break;
      case 4:
        broken = originals[(i + 1) % entries.size()];
        break;
    }
    std::ofstream(entries[i], std::ios::binary | std::ios::trunc) << broken;
  }
  const CommandResult warm = RunShaderport(args, SourceDir());
  EXPECT_EQ(warm.out, cold.out);
  EXPECT_EQ(warm.exit_code, cold.exit_code);
  // Every entry was checked again and written back whole.
  for (size_t i = 0; i < entries.size(); ++i) {
    EXPECT_EQ(ReadWholeFile(entries[i]), originals[i]) << entries[i];
  }
}

TEST_F(CacheCliTest, EditsToAFileItsCommonOrItsConfigAreSeen) {
  const fs::path project = root_ / "project";
  fs::copy(SourceDir() / "tests/data/check-project", project, fs::copy_options::recursive);
  const std::string cached = "check --format json " + CacheOption() + ".";
  auto expect_fresh = [&](const std::string& what) {
    const CommandResult run = RunShaderport(cached, project);
    const CommandResult fresh = RunShaderport("check --format json --no-cache .", project);
    EXPECT_EQ(run.out, fresh.out) << what;
  };
  expect_fresh("cold");
  Write(project / "webgl1/ok.frag", "precision mediump float;\nvoid main() { int x = 1.0; }\n");
  expect_fresh("an edited file");
  Write(project / "toy/common.glsl", "float helper() { return undefined_name; }\n");
  expect_fresh("an edited Common file");
  std::string config = ReadWholeFile(project / ".shaderport.toml");
  config.replace(config.find("\"warning\""), 9, "\"off\"");
  Write(project / ".shaderport.toml", config);
  expect_fresh("an edited config");
  const CommandResult webgl1 = RunShaderport(cached + " --target webgl1", project);
  EXPECT_EQ(webgl1.out, RunShaderport(cached + " --no-cache --target webgl1", project).out);
}

TEST_F(CacheCliTest, RenderRunsAreNotCached) {
  RunShaderport("check --render --render-size 8 " + CacheOption() + "corpus/ao/template.glsl",
                SourceDir());
  EXPECT_TRUE(Entries().empty());
}

}  // namespace
}  // namespace shaderport::testing
