// Fault injection on every file shaderport writes (render -o, merge -o,
// check --write-baseline, report --html, port -o): a write that hits the file-size
// limit or a full disk, a read-only target, and kill -9 at spread-out moments of
// the run. Each must leave the previous file or the complete new one, never a
// torn or empty file, and no temporary.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "cli/child_process.h"
#include "cli/cli_test_util.h"
#include "cli/file_system_conditions.h"
#include "cli/temp_project.h"

namespace shaderport::testing {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kImage =
    "void mainImage(out vec4 c, in vec2 p) { c = vec4(p.x / 64.0, 0.25, 0.5, 1.0); }\n";
constexpr const char* kPrevious = "the previous file, which must survive\n";

struct Writer {
  const char* name;
  std::vector<std::string> args;  // OUT stands for the target
};

// Every writer, with OUT for its target path.
std::vector<Writer> Writers() {
  return {
      {"render", {"render", "--hermetic", "s.frag", "-o", "OUT"}},
      {"merge", {"merge", "-o", "OUT", "a.json"}},
      {"baseline", {"check", "--no-cache", "--write-baseline", "OUT", "warn.frag"}},
      {"report", {"report", "--hermetic", "--html", "OUT", "s.frag"}},
      {"port", {"port", "-o", "OUT", "webgl1.frag"}},
  };
}

std::vector<std::string> WithTarget(const Writer& writer, const std::string& target) {
  std::vector<std::string> args = writer.args;
  for (std::string& word : args) {
    if (word == "OUT") word = target;
  }
  return args;
}

// The inputs every writer reads, in `directory`.
void WriteInputs(const TempProject& project) {
  project.Write("s.frag", kImage);
  project.Write("warn.frag", kFixableEssl3);
  project.Write("webgl1.frag", kWebGL1Fragment);
  project.Write("a.json",
                RunShaderport("check --no-cache --format json warn.frag", project.Root()).out);
}

int RunWriter(const std::vector<std::string>& args, const fs::path& directory,
              rlim_t file_size_limit = RLIM_INFINITY) {
  // Standard error to /dev/null: a file there would itself meet the size limit.
  return WaitForExit(StartShaderport(
      args, {.directory = directory, .err_file = {}, .file_size_limit = file_size_limit}));
}

// No temporary (or anything else) next to the target but what was there.
void ExpectOnly(const fs::path& directory, const std::vector<std::string>& names,
                const std::string& what) {
  EXPECT_EQ(EntriesOf(directory), names) << what;
}

class WriterFaults : public ::testing::TestWithParam<size_t> {
 protected:
  Writer writer_ = Writers()[GetParam()];
};

TEST_P(WriterFaults, FileSizeLimitKeepsThePreviousFile) {
  TempProject project(std::string("fsize-") + writer_.name);
  WriteInputs(project);
  fs::create_directory(project.Root() / "out");
  const fs::path target = project.Root() / "out" / "target";
  project.Write("out/target", kPrevious);
  // 16 bytes: less than any output, so the write of the new text fails midway.
  const int code = RunWriter(WithTarget(writer_, "out/target"), project.Root(), 16);
  EXPECT_GT(code, 0);
  EXPECT_LT(code, 128) << "killed by signal " << code - 128;
  EXPECT_EQ(ReadWholeFile(target), kPrevious);
  ExpectOnly(project.Root() / "out", {"target"}, writer_.name);
}

TEST_P(WriterFaults, ReadOnlyTargetIsRefused) {
  TempProject project(std::string("readonly-") + writer_.name);
  WriteInputs(project);
  const fs::path target = project.Write("target", kPrevious);
  ASSERT_EQ(::chmod(target.c_str(), 0444), 0);
  const int code = RunWriter(WithTarget(writer_, "target"), project.Root());
  EXPECT_GT(code, 0);
  EXPECT_LT(code, 128);
  EXPECT_EQ(ReadWholeFile(target), kPrevious);
  struct stat info {};
  ASSERT_EQ(::stat(target.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 07777, 0444u);
}

TEST_P(WriterFaults, ReplacingKeepsTheMode) {
  TempProject project(std::string("mode-") + writer_.name);
  WriteInputs(project);
  const fs::path target = project.Write("target", kPrevious);
  ASSERT_EQ(::chmod(target.c_str(), 0640), 0);
  EXPECT_LT(RunWriter(WithTarget(writer_, "target"), project.Root()), 2);
  EXPECT_NE(ReadWholeFile(target), kPrevious);
  struct stat info {};
  ASSERT_EQ(::stat(target.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 07777, 0640u);
}

TEST_P(WriterFaults, FullDiskKeepsThePreviousFile) {
  TempProject project(std::string("enospc-") + writer_.name);
  WriteInputs(project);
  fs::create_directories(project.Root() / "disk");
  const TinyTmpfs disk(project.Root() / "disk", 64 * 1024);
  if (!disk.Active()) GTEST_SKIP() << "cannot mount a tmpfs here (needs CAP_SYS_ADMIN)";
  project.Write("disk/target", kPrevious);
  // Fill what is left, so that the new text finds no room.
  std::string filler(4096, 'x');
  for (int i = 0; i < 64; ++i) {
    std::ofstream(project.Root() / "disk" / ("fill" + std::to_string(i)), std::ios::binary)
        << filler;
  }
  const std::vector<std::string> before = EntriesOf(project.Root() / "disk");
  const int code = RunWriter(WithTarget(writer_, "disk/target"), project.Root());
  EXPECT_GT(code, 0);
  EXPECT_LT(code, 128);
  EXPECT_EQ(ReadWholeFile(project.Root() / "disk" / "target"), kPrevious);
  ExpectOnly(project.Root() / "disk", before, writer_.name);
}

// kill -9 at moments spread over an undisturbed run: the target is always the
// previous file or exactly what an undisturbed run writes.
TEST_P(WriterFaults, KillMidRunLeavesOldOrNewFile) {
  TempProject project(std::string("kill-") + writer_.name);
  WriteInputs(project);
  fs::create_directory(project.Root() / "out");
  const auto start = Clock::now();
  ASSERT_LT(RunWriter(WithTarget(writer_, "out/reference"), project.Root()), 2);
  const auto duration = Clock::now() - start;
  const std::string reference = ReadWholeFile(project.Root() / "out" / "reference");
  ASSERT_FALSE(reference.empty());
  fs::remove(project.Root() / "out" / "reference");
  constexpr int kKills = 8;
  int previous_after = 0;
  int new_after = 0;
  for (int round = 0; round < kKills; ++round) {
    project.Write("out/target", kPrevious);
    const pid_t pid =
        StartShaderport(WithTarget(writer_, "out/target"), InDirectory(project.Root()));
    // From a quarter of the run to its end, where the writing happens.
    std::this_thread::sleep_for(duration / 4 + duration * round / (kKills + 1));
    ::kill(pid, SIGKILL);
    WaitForExit(pid);
    const std::string after = ReadWholeFile(project.Root() / "out" / "target");
    const bool writer_is_html = std::string(writer_.name) == "report";
    // The report's page names how long it took: compare its end, not every byte.
    const bool is_new =
        writer_is_html ? after.size() > 1000 && after.ends_with("</html>\n") : after == reference;
    EXPECT_TRUE(after == kPrevious || is_new)
        << "round " << round << ": " << after.size() << " bytes";
    previous_after += after == kPrevious ? 1 : 0;
    new_after += is_new ? 1 : 0;
    ExpectOnly(project.Root() / "out", {"target"}, writer_.name);
  }
  RecordProperty("previous_after_kill", previous_after);
  RecordProperty("new_after_kill", new_after);
}

// The result cache: a write that fails (file-size limit) or a run killed while it
// stores entries leaves no temporary and no entry that a warm run would trust
// wrongly: the warm run prints what a run without the cache prints.
TEST(CacheWriterFaults, FailedAndKilledStoresLeaveNoTornEntry) {
  TempProject project("cache-faults");
  for (int i = 0; i < 12; ++i) {
    project.Write("s/f" + std::to_string(i) + ".frag",
                  std::string(kFixableEssl3) + "// " + std::to_string(i) + "\n");
  }
  const CommandResult plain = RunShaderport("check --no-cache s", project.Root());
  ASSERT_EQ(plain.exit_code, 1);
  const std::vector<std::string> check{"check", "--cache-dir", "cache", "-j", "1", "s"};
  EXPECT_EQ(RunWriter(check, project.Root(), 16), 1);  // no entry fits: every store fails
  const auto start = Clock::now();
  ASSERT_EQ(RunWriter(check, project.Root()), 1);
  const auto duration = Clock::now() - start;
  for (int round = 0; round < 6; ++round) {
    fs::remove_all(project.Root() / "cache");
    const pid_t pid = StartShaderport(check, InDirectory(project.Root()));
    std::this_thread::sleep_for(duration * (round + 1) / 7);
    ::kill(pid, SIGKILL);
    WaitForExit(pid);
    if (fs::exists(project.Root() / "cache")) {
      for (const auto& entry : fs::recursive_directory_iterator(project.Root() / "cache")) {
        EXPECT_FALSE(entry.path().filename().string().ends_with(".tmp")) << entry.path();
      }
    }
    const CommandResult warm = RunShaderport("check --cache-dir cache -j 1 s", project.Root());
    EXPECT_EQ(warm.out, plain.out) << "round " << round;
  }
}

INSTANTIATE_TEST_SUITE_P(EveryWriter, WriterFaults, ::testing::Range<size_t>(0, 5),
                         [](const ::testing::TestParamInfo<size_t>& writer) {
                           return std::string(Writers()[writer.param].name);
                         });

}  // namespace
}  // namespace shaderport::testing
