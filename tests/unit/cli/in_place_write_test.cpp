// `fix --in-place` never loses a file: killed at any moment, through symlinks,
// on a full disk or a read-only directory, and when two runs race.
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/inotify.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "base/file_io/atomic_write.h"
#include "cli/child_process.h"
#include "cli/cli_test_util.h"
#include "cli/file_system_conditions.h"
#include "cli/temp_project.h"

namespace shaderport::testing {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kExitWriteFailed = 3;  // docs/cli.md: an output file could not be written

// What a single, undisturbed `fix` makes of the file (printed, nothing written).
std::string FixedText(const TempProject& project, const std::string& name) {
  const CommandResult result = RunShaderport("fix '" + name + "'", project.Root());
  EXPECT_NE(result.exit_code, kExitWriteFailed) << result.err;
  return result.out;
}

int RunFixInPlace(const TempProject& project, const std::string& name,
                  rlim_t file_size_limit = RLIM_INFINITY, std::string* err = nullptr) {
  const fs::path err_file =
      project.Root().parent_path() / ("in-place-" + std::to_string(::getpid()) + ".err");
  const pid_t pid = StartShaderport(
      {"fix", "--in-place", name},
      {.directory = project.Root(), .err_file = err_file, .file_size_limit = file_size_limit});
  const int code = WaitForExit(pid);
  if (err != nullptr) *err = ReadWholeFile(err_file);
  fs::remove(err_file);
  return code;
}

// When an undisturbed `fix --in-place` opens the file, renames the new text
// onto it, and exits, from its start (inotify on the directory).
struct Timeline {
  std::chrono::microseconds opened{0};
  std::chrono::microseconds writing{0};  // WriteFileAtomically opens the directory
  std::chrono::microseconds renamed{0};
  std::chrono::microseconds finished{0};
};

Timeline TimeFixInPlace(const TempProject& project, const std::string& name) {
  Timeline timeline;
  const int watch = ::inotify_init1(IN_CLOEXEC);
  EXPECT_GE(::inotify_add_watch(watch, project.Root().c_str(), IN_OPEN | IN_MOVED_TO), 0);
  const auto start = Clock::now();
  auto since_start = [&] {
    return std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - start);
  };
  const pid_t pid = StartShaderport({"fix", "--in-place", name}, InDirectory(project.Root()));
  alignas(inotify_event) char buffer[4096];
  while (timeline.renamed.count() == 0) {
    pollfd ready{watch, POLLIN, 0};
    if (::poll(&ready, 1, 60'000) != 1) break;
    const ssize_t n = ::read(watch, buffer, sizeof buffer);
    for (ssize_t at = 0; at < n;) {
      const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
      const bool ours = event->len > 0 && std::string(event->name) == name;
      if (ours && (event->mask & IN_OPEN) != 0 && timeline.opened.count() == 0) {
        timeline.opened = since_start();
      }
      const bool directory = event->len == 0 && (event->mask & IN_ISDIR) != 0;
      if (directory && (event->mask & IN_OPEN) != 0 && timeline.opened.count() != 0 &&
          timeline.writing.count() == 0) {
        timeline.writing = since_start();
      }
      if (ours && (event->mask & IN_MOVED_TO) != 0) timeline.renamed = since_start();
      at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
    }
  }
  EXPECT_EQ(WaitForExit(pid), 0);
  timeline.finished = since_start();
  ::close(watch);
  return timeline;
}

TEST(InPlaceWrite, SigkillLeavesOriginalOrFixedTextAndNoTemporary) {
  const TempProject project("inplace-kill");
  const std::string original = FixableShaderToy(1 << 20, 200);  // 1 MiB
  const fs::path file = project.Write("big.glsl", original);
  const std::string fixed = FixedText(project, "big.glsl");
  ASSERT_NE(fixed, original) << "fix must have work to do";
  ASSERT_EQ(fixed.size(), original.size() + 200 * 6);  // "2" -> "2.0" three times a function

  // The faster of two runs: a load spike on the machine would stretch the delays.
  const Timeline first = TimeFixInPlace(project, "big.glsl");
  ASSERT_EQ(ReadWholeFile(file), fixed);
  project.Write("big.glsl", original);
  const Timeline second = TimeFixInPlace(project, "big.glsl");
  ASSERT_EQ(ReadWholeFile(file), fixed);
  const Timeline timeline = first.finished < second.finished ? first : second;
  ASSERT_LE(timeline.opened, timeline.writing);
  ASSERT_LT(timeline.writing, timeline.renamed);

  // A third of the kills land anywhere in a run, a third between the moment fix
  // opens the file and its rename (reading, fixing, writing), a third while it
  // writes (temporary, write, fsync, link, rename), where a file could be lost.
  constexpr int kKills = 30;
  std::mt19937 random(14);
  using Delay = std::uniform_int_distribution<int64_t>;
  Delay delays[3] = {Delay(0, timeline.finished.count()),
                     Delay(timeline.opened.count(), timeline.renamed.count()),
                     Delay(timeline.writing.count(), timeline.renamed.count() + 500)};
  int original_after = 0, fixed_after = 0, finished_before_kill = 0, temporaries_left = 0;
  for (int round = 0; round < kKills; ++round) {
    if (ReadWholeFile(file) != original) project.Write("big.glsl", original);
    const auto delay = std::chrono::microseconds(delays[round % 3](random));
    const pid_t pid =
        StartShaderport({"fix", "--in-place", "big.glsl"}, InDirectory(project.Root()));
    ASSERT_GT(pid, 0);
    std::this_thread::sleep_for(delay);
    ::kill(pid, SIGKILL);
    if (WaitForExit(pid) != 128 + SIGKILL) ++finished_before_kill;

    const std::string after = ReadWholeFile(file);
    ASSERT_TRUE(after == original || after == fixed)
        << "round " << round << ": " << after.size() << " bytes, neither the original ("
        << original.size() << ") nor the fixed text (" << fixed.size() << ")";
    ++(after == original ? original_after : fixed_after);
    std::vector<std::string> entries = EntriesOf(project.Root());
    if (entries.size() == 2) {
      // Only a kill between linkat() and rename(), microseconds apart, leaves a
      // (complete) temporary; a later write removes it once it is stale.
      const std::string left = entries[0] == "big.glsl" ? entries[1] : entries[0];
      ASSERT_TRUE(file_io::IsAtomicWriteTemporary(left)) << left;
      EXPECT_EQ(ReadWholeFile(project.Root() / left), fixed);
      ++temporaries_left;
      const timespec hour_ago[2] = {{::time(nullptr) - 3600, 0}, {::time(nullptr) - 3600, 0}};
      ASSERT_EQ(::utimensat(AT_FDCWD, (project.Root() / left).c_str(), hour_ago, 0), 0);
      project.Write("big.glsl", original);
      ASSERT_EQ(RunFixInPlace(project, "big.glsl"), 0);
      entries = EntriesOf(project.Root());
    }
    ASSERT_EQ(entries, std::vector<std::string>{"big.glsl"}) << "round " << round;
  }
  std::printf(
      "%d kills (a run: file opened at %lld ms, written from %lld ms, renamed at %lld ms, exit "
      "at %lld ms): %d left "
      "the original, %d the fixed text, %d runs finished first, %d left a temporary\n",
      kKills, static_cast<long long>(timeline.opened.count() / 1000),
      static_cast<long long>(timeline.writing.count() / 1000),
      static_cast<long long>(timeline.renamed.count() / 1000),
      static_cast<long long>(timeline.finished.count() / 1000), original_after, fixed_after,
      finished_before_kill, temporaries_left);
  RecordProperty("kills", kKills);
  RecordProperty("fixed_after_kill", fixed_after);
}

TEST(InPlaceWrite, SymlinkStaysALinkAndItsTargetIsFixed) {
  const TempProject project("inplace-symlink");
  const std::string original = FixableShaderToy(0, 3);
  project.Write("real/real.glsl", original);
  const std::string fixed = FixedText(project, "real/real.glsl");
  fs::create_directories(project.Root() / "shaders");
  fs::create_symlink("../real/real.glsl", project.Root() / "shaders/link.glsl");

  ASSERT_EQ(RunFixInPlace(project, "shaders/link.glsl"), 0);
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(project.Root() / "shaders/link.glsl")));
  EXPECT_EQ(fs::read_symlink(project.Root() / "shaders/link.glsl"), "../real/real.glsl");
  EXPECT_EQ(ReadWholeFile(project.Root() / "real/real.glsl"), fixed);
  EXPECT_EQ(EntriesOf(project.Root() / "real"), std::vector<std::string>{"real.glsl"});
  EXPECT_EQ(EntriesOf(project.Root() / "shaders"), std::vector<std::string>{"link.glsl"});
}

TEST(InPlaceWrite, ModeAndOwnerAreKept) {
  const TempProject project("inplace-mode");
  const fs::path file = project.Write("a.glsl", FixableShaderToy(0, 3));
  const std::string fixed = FixedText(project, "a.glsl");
  ASSERT_EQ(::chmod(file.c_str(), 0640), 0);
  const bool root = ::geteuid() == 0;
  if (root) {
    ASSERT_EQ(::chown(file.c_str(), 4242, 4343), 0);  // someone else's file
  }

  ASSERT_EQ(RunFixInPlace(project, "a.glsl"), 0);
  EXPECT_EQ(ReadWholeFile(file), fixed);
  struct stat info {};
  ASSERT_EQ(::stat(file.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 07777, 0640u);
  if (root) {
    EXPECT_EQ(info.st_uid, 4242u);
    EXPECT_EQ(info.st_gid, 4343u);
  } else {
    EXPECT_EQ(info.st_uid, ::geteuid());
  }
}

// The failed write must leave the original, no temporary, exit 3 and say why.
void ExpectRefused(const fs::path& directory, const std::string& name, const std::string& original,
                   int code, const std::string& err, const std::string& reason) {
  EXPECT_EQ(code, kExitWriteFailed) << err;
  EXPECT_NE(err.find("shaderport: error: cannot write " + name), std::string::npos) << err;
  EXPECT_NE(err.find(reason), std::string::npos) << err;
  EXPECT_NE(err.find("the file is unchanged"), std::string::npos) << err;
  EXPECT_EQ(ReadWholeFile(directory / fs::path(name).filename()), original);
  EXPECT_EQ(EntriesOf(directory), std::vector<std::string>{fs::path(name).filename().string()});
}

// Root ignores permission bits, so for root the immutable flag stands in.
TEST(InPlaceWrite, ReadOnlyDirectoryLeavesTheOriginal) {
  const TempProject project("inplace-rodir");
  const std::string original = FixableShaderToy(0, 3);
  const fs::path file = project.Write("ro/a.glsl", original);
  const fs::path directory = file.parent_path();
  ImmutableFlag immutable(::geteuid() == 0 ? directory : fs::path());
  if (::geteuid() == 0 && !immutable.Active()) {
    GTEST_SKIP() << "running as root without CAP_LINUX_IMMUTABLE: no directory refuses root";
  }
  if (::geteuid() != 0) {
    ASSERT_EQ(::chmod(directory.c_str(), 0555), 0);
  }
  std::string err;
  const int code = RunFixInPlace(project, "ro/a.glsl", RLIM_INFINITY, &err);
  ::chmod(directory.c_str(), 0755);
  ExpectRefused(directory, "ro/a.glsl", original, code, err, "creating a temporary file in ro");
}

// Refused by its mode bits, so also for root, whom access() lets write anything.
TEST(InPlaceWrite, ReadOnlyFileLeavesTheOriginal) {
  const TempProject project("inplace-rofile");
  const std::string original = FixableShaderToy(0, 3);
  const fs::path file = project.Write("a.glsl", original);
  ASSERT_EQ(::chmod(file.c_str(), 0444), 0);
  std::string err;
  const int code = RunFixInPlace(project, "a.glsl", RLIM_INFINITY, &err);
  ExpectRefused(project.Root(), "a.glsl", original, code, err, "the file is read-only");
  struct stat info {};
  ASSERT_EQ(::stat(file.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 07777, 0444u);
}

TEST(InPlaceWrite, FullDiskLeavesTheOriginal) {
  const TempProject project("inplace-enospc");
  fs::create_directories(project.Root() / "disk");
  const TinyTmpfs disk(project.Root() / "disk", 64 * 1024);
  if (!disk.Active()) {
    GTEST_SKIP() << "cannot mount a tmpfs here (needs CAP_SYS_ADMIN); "
                    "FileSizeLimitLeavesTheOriginal covers a write that fails midway";
  }
  // 40 KB fill 10 of the 16 pages: the second copy cannot fit.
  const std::string original = FixableShaderToy(40 * 1024, 20);
  project.Write("disk/a.glsl", original);
  ASSERT_NE(FixedText(project, "disk/a.glsl"), original);
  std::string err;
  const int code = RunFixInPlace(project, "disk/a.glsl", RLIM_INFINITY, &err);
  ExpectRefused(project.Root() / "disk", "disk/a.glsl", original, code, err,
                "writing the new text): No space left on device");
}

// RLIMIT_FSIZE fails the write with EFBIG for any user, and raises SIGXFSZ,
// which kills a process that does not block or ignore it (it is left at its
// default here).
TEST(InPlaceWrite, FileSizeLimitLeavesTheOriginal) {
  const TempProject project("inplace-efbig");
  const std::string original = FixableShaderToy(40 * 1024, 20);
  project.Write("a.glsl", original);
  ASSERT_NE(FixedText(project, "a.glsl"), original);
  std::string err;
  const int code = RunFixInPlace(project, "a.glsl", 16 * 1024, &err);
  ExpectRefused(project.Root(), "a.glsl", original, code, err,
                "writing the new text): File too large");
}

int LockExclusively(const fs::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  EXPECT_GE(fd, 0);
  EXPECT_EQ(::flock(fd, LOCK_EX), 0);
  return fd;
}

// A run waits for the lock, and when the holder renamed a new file in, waits
// for that file's lock too and then fixes the new text, not the old one.
TEST(InPlaceWrite, WaitsForTheLockAndFixesTheFileThatReplacedIt) {
  const TempProject project("inplace-lock");
  const std::string first = FixableShaderToy(0, 2);
  const std::string second = FixableShaderToy(0, 5);
  project.Write("b.glsl", second);
  const std::string second_fixed = FixedText(project, "b.glsl");
  const fs::path file = project.Write("a.glsl", first);

  const int old_lock = LockExclusively(file);
  const pid_t pid = StartShaderport({"fix", "--in-place", "a.glsl"}, InDirectory(project.Root()));
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  EXPECT_TRUE(StillRunning(pid)) << "fix did not wait for the lock";
  EXPECT_EQ(ReadWholeFile(file), first);

  // Another writer renames a new file in, holding that file's lock.
  const int new_lock = LockExclusively(project.Root() / "b.glsl");
  fs::rename(project.Root() / "b.glsl", file);
  ::close(old_lock);
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  EXPECT_TRUE(StillRunning(pid)) << "fix took the lock of a file the path no longer names";
  EXPECT_EQ(ReadWholeFile(file), second);

  ::close(new_lock);
  EXPECT_EQ(WaitForExit(pid), 0);
  EXPECT_EQ(ReadWholeFile(file), second_fixed);
}

// inotify counts the temporaries linked into the directory (renames onto one
// name would be coalesced): one run writes, the other waits and finds nothing
// left to fix.
TEST(InPlaceWrite, TwoConcurrentRunsWriteOnceAndGiveTheSingleRunResult) {
  const TempProject project("inplace-race");
  const std::string original = FixableShaderToy(0, 300);
  const fs::path file = project.Write("a.glsl", original);
  const std::string fixed = FixedText(project, "a.glsl");
  ASSERT_NE(fixed, original);
  const int watch = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  ASSERT_GE(watch, 0);
  ASSERT_GE(::inotify_add_watch(watch, project.Root().c_str(), IN_CREATE), 0);

  constexpr int kRounds = 6;
  for (int round = 0; round < kRounds; ++round) {
    project.Write("a.glsl", original);
    const pid_t one = StartShaderport({"fix", "--in-place", "a.glsl"}, InDirectory(project.Root()));
    const pid_t two = StartShaderport({"fix", "--in-place", "a.glsl"}, InDirectory(project.Root()));
    EXPECT_EQ(WaitForExit(one), 0);
    EXPECT_EQ(WaitForExit(two), 0);
    ASSERT_EQ(ReadWholeFile(file), fixed) << "round " << round;
    EXPECT_EQ(EntriesOf(project.Root()), std::vector<std::string>{"a.glsl"});
    int writes = 0;
    alignas(inotify_event) char buffer[4096];
    ssize_t n = 0;
    while ((n = ::read(watch, buffer, sizeof buffer)) > 0) {
      for (ssize_t at = 0; at < n;) {
        const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
        if (event->len > 0 && file_io::IsAtomicWriteTemporary(event->name)) ++writes;
        at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
      }
    }
    EXPECT_EQ(writes, 1) << "round " << round << ": both runs wrote";
  }
  ::close(watch);
}

}  // namespace
}  // namespace shaderport::testing
