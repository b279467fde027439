// The render child's sandbox through the real binary (docs/render.md, Isolation):
// a shader past the timeout is killed and reported, an allocation past the
// address-space limit is reported, no render process outlives a SIGKILLed
// parent, and ShaderToy JSON pass names never become paths.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "bounded_run.h"
#include "temp_project.h"

namespace shaderport::testing {
namespace {

namespace fs = std::filesystem;
using std::chrono::steady_clock;

// Heavy work in a loop llvmpipe caps at 65,535 iterations per pixel: minutes of
// drawing at 128x128, so only the timeout ends it.
constexpr const char* kSpinningShader =
    "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
    "  vec4 x = vec4(fragCoord, 0.0, 1.0);\n"
    "  for (int i = 0; i < 1000000; i++) {\n"
    "    x = sin(x * 1.0001 + cos(x.yzwx)) + exp(-abs(x.zwxy)) * tan(x.wxyz);\n"
    "    x = sin(x * 1.0001 + cos(x.yzwx)) + exp(-abs(x.zwxy)) * tan(x.wxyz);\n"
    "    x = sin(x * 1.0001 + cos(x.yzwx)) + exp(-abs(x.zwxy)) * tan(x.wxyz);\n"
    "    x = sin(x * 1.0001 + cos(x.yzwx)) + exp(-abs(x.zwxy)) * tan(x.wxyz);\n"
    "  }\n"
    "  fragColor = x;\n"
    "}\n";

// An 800 MB local array: Mesa's compiler and llvmpipe allocate far past 1 GiB.
constexpr const char* kHugeArrayShader =
    "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
    "  float a[200000000];\n"
    "  for (int i = 0; i < 200000000; i++) a[i] = float(i);\n"
    "  fragColor = vec4(a[int(fragCoord.x)], 0.0, 0.0, 1.0);\n"
    "}\n";

constexpr const char* kSmallShader =
    "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
    "  fragColor = vec4(fragCoord / 64.0, 0.5, 1.0);\n"
    "}\n";

class RenderSandboxTest : public ::testing::Test {
 protected:
  BoundedRun Run(const std::vector<std::string>& args, BoundedRunOptions options = {}) {
    options.directory = project_.Root();
    return RunBounded(args, options);
  }
  TempProject project_{"render-sandbox"};
};

TEST_F(RenderSandboxTest, ShaderPastTheTimeoutIsKilledAndReported) {
  project_.Write("spin.frag", kSpinningShader);
  const BoundedRun render =
      Run({"render", "spin.frag", "--size", "128x128", "--timeout", "1", "--hermetic"});
  EXPECT_EQ(render.exit_code, 1) << render.Printed();
  EXPECT_NE(render.err.find("spin.frag:1:1: error: the render did not finish within 1000 ms and "
                            "was killed [render/timeout]"),
            std::string::npos)
      << render.Printed();
  EXPECT_LT(render.seconds, 10);
  const BoundedRun check = Run({"check", "--no-cache", "--render", "--render-size", "128",
                                "--render-timeout", "1", "spin.frag"});
  EXPECT_EQ(check.exit_code, 1) << check.Printed();
  EXPECT_NE(check.out.find("[render/timeout]"), std::string::npos) << check.Printed();
  EXPECT_LT(check.seconds, 10);
}

// The child's RLIMIT_AS is 4 GiB, lowered to whatever the caller set: as root the
// child used to raise a caller's 1 GiB back to 4 GiB (and crawled on for 30 s).
TEST_F(RenderSandboxTest, AllocationPastTheMemoryLimitIsReported) {
  if (kSanitizedBuild) GTEST_SKIP() << "ASan builds render without an address-space limit";
  project_.Write("huge.frag", kHugeArrayShader);
  project_.Write("small.frag", kSmallShader);
  BoundedRunOptions one_gib;
  one_gib.address_space = rlim_t{1} << 30;
  const BoundedRun small =
      Run({"render", "small.frag", "-o", "small.png", "--hermetic", "--timeout", "15"}, one_gib);
  EXPECT_EQ(small.exit_code, 0) << "1 GiB is enough for an ordinary render\n" << small.Printed();
  const BoundedRun huge =
      Run({"render", "huge.frag", "-o", "huge.png", "--hermetic", "--timeout", "15"}, one_gib);
  EXPECT_EQ(huge.exit_code, 1) << huge.Printed();
  EXPECT_NE(huge.err.find("[render/crashed]"), std::string::npos) << huge.Printed();
  EXPECT_NE(huge.err.find("out of memory"), std::string::npos) << huge.Printed();
  EXPECT_NE(huge.err.find("address-space limit 1024 MiB"), std::string::npos) << huge.Printed();
  EXPECT_LT(huge.seconds, 10) << "the limit, not the timeout, must end it";
  EXPECT_FALSE(fs::exists(project_.Root() / "huge.png"));
}

// Pids of live (not zombie) processes whose environment holds `marker`.
std::set<pid_t> ProcessesWithMarker(const std::string& marker) {
  std::set<pid_t> found;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream environ(entry.path() / "environ", std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(environ)), {});
    if (text.find(marker) == std::string::npos) continue;
    std::ifstream stat(entry.path() / "stat");
    std::string stat_text((std::istreambuf_iterator<char>(stat)), {});
    const size_t close = stat_text.rfind(')');
    if (close != std::string::npos && close + 2 < stat_text.size() && stat_text[close + 2] == 'Z') {
      continue;
    }
    found.insert(static_cast<pid_t>(std::stoi(name)));
  }
  return found;
}

// Without PR_SET_PDEATHSIG the spinning render child ran on after its parent died.
TEST_F(RenderSandboxTest, NoRenderProcessOutlivesAKilledParent) {
  project_.Write("spin.frag", kSpinningShader);
  const std::string marker = "SHADERPORT_SANDBOX_TEST_MARKER=" + std::to_string(::getpid()) + "-" +
                             std::to_string(steady_clock::now().time_since_epoch().count());
  std::vector<std::string> words = {SHADERPORT_BINARY, "render",    "spin.frag", "--size",
                                    "128x128",         "--timeout", "60",        "--hermetic"};
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const std::string directory = project_.Root().string();
  const pid_t parent = ::fork();
  ASSERT_GE(parent, 0);
  if (parent == 0) {
    if (::chdir(directory.c_str()) != 0) ::_exit(126);
    ::putenv(const_cast<char*>(marker.c_str()));
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  // Wait until the render child exists (two processes carry the marker).
  const auto deadline = steady_clock::now() + std::chrono::seconds(20);
  std::set<pid_t> processes;
  while (steady_clock::now() < deadline) {
    processes = ProcessesWithMarker(marker);
    if (processes.size() >= 2) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_GE(processes.size(), 2u) << "the render child never started";
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // it is drawing now
  ::kill(parent, SIGKILL);
  int status = 0;
  ::waitpid(parent, &status, 0);
  const auto gone_by = steady_clock::now() + std::chrono::seconds(5);
  while (!ProcessesWithMarker(marker).empty() && steady_clock::now() < gone_by) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  const std::set<pid_t> survivors = ProcessesWithMarker(marker);
  EXPECT_TRUE(survivors.empty()) << "a render process survived its parent";
  for (const pid_t pid : survivors) ::kill(pid, SIGKILL);
}

// Pass names in a ShaderToy JSON export only name sources in diagnostics: no file
// is written from them, whatever they hold.
TEST_F(RenderSandboxTest, JsonPassNamesNeverBecomePaths) {
  const fs::path outside = project_.Root() / "outside";
  fs::create_directories(project_.Root() / "work/deep");
  const std::string escape = (outside / "abs").string();
  const std::string json =
      R"({"ver":"0.1","info":{"id":"x","name":"../../evil"},"renderpass":[],"passes":[)"
      R"({"name":"../../escaped","type":"buffer","code":"void mainImage(out vec4 o, in vec2 p) { o = vec4(1.0); }","inputs":[],"outputs":[]},)"
      R"({"name":")" +
      escape +
      R"(","type":"buffer","code":"void mainImage(out vec4 o, in vec2 p) { o = vec4(0.5); }","inputs":[],"outputs":[]},)"
      R"({"name":"a/b/../../c","type":"common","code":"float common_value() { return 0.25; }"},)"
      R"({"name":"../../image/..","type":"image","code":"void mainImage(out vec4 o, in vec2 p) { o = vec4(p / 64.0, common_value(), 1.0) + undefined_name; }","inputs":[],"outputs":[]}]})";
  project_.Write("work/deep/shader.json", json);
  auto listing = [&] {
    std::set<std::string> paths;
    for (const auto& entry : fs::recursive_directory_iterator(project_.Root())) {
      paths.insert(entry.path().lexically_relative(project_.Root()).string());
    }
    return paths;
  };
  const std::set<std::string> before = listing();
  BoundedRunOptions options;
  options.directory = project_.Root() / "work/deep";
  const BoundedRun render =
      RunBounded({"render", "shader.json", "-o", "out.png", "--hermetic"}, options);
  EXPECT_EQ(render.exit_code, 1) << render.Printed();
  // The error is placed in the pass, under its name, as a label only.
  EXPECT_NE(render.err.find("shader.json#../../image/..:1:"), std::string::npos)
      << render.Printed();
  std::set<std::string> after = listing();
  after.erase("work/deep/out.png");
  EXPECT_EQ(after, before);
  EXPECT_FALSE(fs::exists(outside));
  for (const std::string command : {"check", "port"}) {
    std::vector<std::string> args = {command, "shader.json"};
    if (command == "port") args = {"port", "--out-dir", "ported", "shader.json"};
    const BoundedRun run = RunBounded(args, options);
    EXPECT_TRUE(run.exit_code == 1 || run.exit_code == 2) << command << run.Printed();
    EXPECT_FALSE(fs::exists(outside)) << command;
  }
}

}  // namespace
}  // namespace shaderport::testing
