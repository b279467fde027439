// What every command reads and writes besides its inputs' text: an output that is
// one of the inputs is refused (by file identity), and a baseline, a report to
// merge, a config, a channel image or a cache entry that is a FIFO or /dev/zero is
// a diagnostic, not a hang or an unbounded read.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "cli/child_process.h"
#include "cli/cli_test_util.h"
#include "cli/temp_project.h"

namespace shaderport::testing {
namespace {

namespace fs = std::filesystem;

constexpr const char* kImage = "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.5); }\n";

struct Finished {
  int exit_code = -1;
  bool hung = false;
  std::string err;
};

// Runs shaderport ARGS in `directory`, killing it after `seconds`: a hang fails
// the test instead of blocking the suite.
Finished RunWithDeadline(const std::vector<std::string>& args, const fs::path& directory,
                         int seconds = 30) {
  const fs::path err_file = directory / ".err";
  const pid_t pid = StartShaderport(args, {.directory = directory, .err_file = err_file});
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  Finished finished;
  while (StillRunning(pid) && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (StillRunning(pid)) {
    ::kill(pid, SIGKILL);
    finished.hung = true;
  }
  finished.exit_code = WaitForExit(pid);
  finished.err = ReadWholeFile(err_file);
  fs::remove(err_file);
  return finished;
}

void ExpectRefusedAndUnchanged(const TempProject& project, const std::string& args,
                               const std::string& file, const std::string& before) {
  const CommandResult result = RunShaderport(args, project.Root());
  EXPECT_EQ(result.exit_code, 2) << args << "\n" << result.out << result.err;
  EXPECT_NE(result.err.find("is the input"), std::string::npos) << args << "\n" << result.err;
  EXPECT_EQ(ReadWholeFile(project.Root() / file), before) << args;
}

TEST(OutputIsInputCli, EveryWriterRefusesToReplaceAnInput) {
  TempProject project("output-is-input");
  project.Write("s.frag", kImage);
  project.Write("r.glsl", kImage);
  project.Write("w.frag", kWebGL1Fragment);
  fs::create_directory_symlink(".", project.Root() / "here");
  fs::create_hard_link(project.Root() / "s.frag", project.Root() / "hard.frag");
  for (const std::string& args : {
           std::string("report --html s.frag s.frag"),
           std::string("report --hermetic --html s.frag here"),
           std::string("check --write-baseline s.frag s.frag"),
           std::string("check --no-cache --write-baseline ./s.frag here"),
           std::string("render r.glsl -o r.glsl"),
           std::string("render r.glsl -o here/r.glsl"),
           std::string("render r.glsl --channel0 s.frag -o hard.frag"),
           std::string("port -o w.frag w.frag"),
           std::string("port -o hard.frag s.frag"),
       }) {
    const std::string file =
        args.find("w.frag") != std::string::npos ? "w.frag"
        : args.find("r.glsl") != std::string::npos && args.find("hard") == std::string::npos
            ? "r.glsl"
            : "s.frag";
    ExpectRefusedAndUnchanged(project, args, file, ReadWholeFile(project.Root() / file));
  }
  // merge: one of the reports it joins.
  const CommandResult shard = RunShaderport("check --format json s.frag", project.Root());
  project.Write("a.json", shard.out);
  ExpectRefusedAndUnchanged(project, "merge -o a.json a.json", "a.json", shard.out);
}

TEST(OutputIsInputCli, ReadOnlyTargetIsRefusedEvenForRoot) {
  TempProject project("read-only-target");
  project.Write("s.frag", kImage);
  const fs::path target = project.Write("out.png", "previous");
  ASSERT_EQ(::chmod(target.c_str(), 0444), 0);
  const CommandResult result = RunShaderport("render --hermetic s.frag -o out.png", project.Root());
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_NE(result.err.find("read-only"), std::string::npos) << result.err;
  EXPECT_EQ(ReadWholeFile(target), "previous");
  const fs::path merged = project.Write("merged.json", "previous");
  ASSERT_EQ(::chmod(merged.c_str(), 0444), 0);
  project.Write("a.json", RunShaderport("check --format json s.frag", project.Root()).out);
  const CommandResult merge = RunShaderport("merge -o merged.json a.json", project.Root());
  EXPECT_NE(merge.exit_code, 0);
  EXPECT_NE(merge.err.find("read-only"), std::string::npos) << merge.err;
  EXPECT_EQ(ReadWholeFile(merged), "previous");
}

TEST(BoundedReadsCli, BaselinesReportsImagesAndDialectsMustBeRegularFiles) {
  TempProject project("bounded-reads");
  project.Write("s.frag", kImage);
  ASSERT_EQ(::mkfifo((project.Root() / "fifo").c_str(), 0644), 0);
  struct Case {
    std::vector<std::string> args;
    std::string says;
    int exit_code = 2;  // a usage error; a channel image is a finding of the render (1)
  };
  const std::string regular = "not a regular file";
  for (const Case& run : std::vector<Case>{
           {{"check", "--no-cache", "--baseline", "/dev/zero", "s.frag"}, regular},
           {{"check", "--no-cache", "--baseline", "fifo", "s.frag"}, regular},
           {{"merge", "/dev/zero"}, regular},
           {{"merge", "fifo"}, regular},
           {{"render", "--hermetic", "s.frag", "--channel0", "fifo"}, regular, 1},
           {{"render", "--hermetic", "s.frag", "--channel0", "/dev/zero"}, regular, 1},
           {{"port", "--dialect", "fifo", "s.frag"}, "nor a readable dialect file"},
       }) {
    const Finished finished = RunWithDeadline(run.args, project.Root());
    std::string joined;
    for (const std::string& word : run.args) joined += word + " ";
    EXPECT_FALSE(finished.hung) << joined;
    EXPECT_EQ(finished.exit_code, run.exit_code) << joined << finished.err;
    EXPECT_NE(finished.err.find(run.says), std::string::npos) << joined << finished.err;
  }
}

TEST(BoundedReadsCli, ConfigThatIsAFifoIsADiagnostic) {
  TempProject project("fifo-config");
  project.Write("s.frag", kImage);
  ASSERT_EQ(::mkfifo((project.Root() / ".shaderport.toml").c_str(), 0644), 0);
  const Finished finished = RunWithDeadline({"check", "--no-cache", "s.frag"}, project.Root());
  EXPECT_FALSE(finished.hung);
  EXPECT_NE(finished.exit_code, 3) << finished.err;
  const Finished given = RunWithDeadline(
      {"check", "--no-cache", "--config", ".shaderport.toml", "s.frag"}, project.Root());
  EXPECT_FALSE(given.hung);
  EXPECT_NE(given.exit_code, 0);
  EXPECT_NE(given.exit_code, 3) << given.err;
}

TEST(BoundedReadsCli, FifoInTheCacheIsAMiss) {
  TempProject project("fifo-cache");
  project.Write("s.frag", kFixableEssl3);
  const std::vector<std::string> check{"check", "--cache-dir", "cache", "s.frag"};
  const Finished cold = RunWithDeadline(check, project.Root());
  ASSERT_EQ(cold.exit_code, 1) << cold.err;
  // Every entry replaced by a FIFO with no writer: each is ignored (a miss).
  size_t planted = 0;
  for (const auto& entry : fs::recursive_directory_iterator(project.Root() / "cache")) {
    if (!entry.is_regular_file() || entry.path().filename().string().size() != 32) continue;
    fs::remove(entry.path());
    ASSERT_EQ(::mkfifo(entry.path().c_str(), 0644), 0);
    ++planted;
  }
  ASSERT_GT(planted, 0u);
  const Finished warm = RunWithDeadline(check, project.Root());
  EXPECT_FALSE(warm.hung);
  EXPECT_EQ(warm.exit_code, 1) << warm.err;
}

// Someone who can write in the cache directory plants a symlink where an entry will
// be stored: the store must not write through it (as root, into any file).
TEST(BoundedReadsCli, SymlinkPlantedInTheCacheIsNotWrittenThrough) {
  TempProject project("symlink-cache");
  project.Write("s.frag", kFixableEssl3);
  const std::vector<std::string> check{"check", "--cache-dir", "cache", "s.frag"};
  ASSERT_EQ(RunWithDeadline(check, project.Root()).exit_code, 1);
  const fs::path victim = project.Write("victim.txt", "keep me\n");
  size_t planted = 0;
  for (const auto& entry : fs::recursive_directory_iterator(project.Root() / "cache")) {
    if (!entry.is_regular_file() || entry.path().filename().string().size() != 32) continue;
    fs::remove(entry.path());
    fs::create_symlink(victim, entry.path());
    ++planted;
  }
  ASSERT_GT(planted, 0u);
  const Finished again = RunWithDeadline(check, project.Root());
  EXPECT_EQ(again.exit_code, 1) << again.err;
  EXPECT_EQ(ReadWholeFile(victim), "keep me\n");
}

}  // namespace
}  // namespace shaderport::testing

namespace shaderport::testing {
namespace {

// `"channel": "0"` once made every command exit 3 with nlohmann's type_error.
TEST(ProjectMembersCli, WrongTypedMemberIsAFindingAndTheOtherFilesAreChecked) {
  TempProject project("wrong-typed-member");
  project.Write("d/p.json",
                R"({"Shader":{"info":{"id":"x"},"renderpass":[{"type":"image","name":"Image",)"
                R"("code":"void mainImage(out vec4 c, in vec2 p) { c = vec4(1); }",)"
                R"("inputs":[{"channel":"0","ctype":"buffer"}]}]}})");
  project.Write("d/other.frag", kFixableEssl3);
  const CommandResult check = RunShaderport("check --no-cache d", project.Root());
  EXPECT_EQ(check.exit_code, 1) << check.err;
  EXPECT_NE(check.out.find("d/p.json:1:"), std::string::npos) << check.out;
  EXPECT_NE(check.out.find("\"channel\" at /Shader/renderpass/0/inputs/0/channel must be an "
                           "integer from 0 to 3, not a string [input/invalid-project]"),
            std::string::npos)
      << check.out;
  EXPECT_NE(check.out.find("d/other.frag:"), std::string::npos) << check.out;
  for (const std::string& args :
       {std::string("fix --diff d"), std::string("port --out-dir out d"),
        std::string("render --hermetic d/p.json"), std::string("report --hermetic --html r.html d"),
        std::string("fix -i d/p.json")}) {
    const CommandResult result = RunShaderport(args, project.Root());
    EXPECT_NE(result.exit_code, 3) << args << "\n" << result.err;
    EXPECT_EQ(result.err.find("internal error"), std::string::npos) << args << result.err;
  }
}

}  // namespace
}  // namespace shaderport::testing
