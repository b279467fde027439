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
#include "render_process_support.h"
#include "temp_project.h"

namespace shaderport::testing {
namespace {

namespace fs = std::filesystem;
using std::chrono::steady_clock;

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

// Without PR_SET_PDEATHSIG the spinning render child ran on after its parent died.
TEST_F(RenderSandboxTest, NoRenderProcessOutlivesAKilledParent) {
  project_.Write("spin.frag", kSpinningShader);
  const KilledParentRun run = RunAndKillParent(
      {"render", "spin.frag", "--size", "128x128", "--timeout", "60", "--hermetic"},
      project_.Root(), {}, std::chrono::milliseconds(300));
  EXPECT_TRUE(run.render_started) << "the render child never started";
  EXPECT_TRUE(run.survivors.empty()) << "a render process survived its parent";
}

// Pass names in a ShaderToy JSON export only name sources in diagnostics: no file
// is written from them, whatever they hold. (The buffers name their outputs by id:
// a buffer that names no Buffer A-D is an invalid project for render as for check.)
TEST_F(RenderSandboxTest, JsonPassNamesNeverBecomePaths) {
  const fs::path outside = project_.Root() / "outside";
  fs::create_directories(project_.Root() / "work/deep");
  const std::string escape = (outside / "abs").string();
  const std::string json =
      R"({"ver":"0.1","info":{"id":"x","name":"../../evil"},"passes":[)"
      R"({"name":"../../escaped","type":"buffer","code":"void mainImage(out vec4 o, in vec2 p) { o = vec4(1.0); }","inputs":[],"outputs":[{"id":"4dXGR8","channel":0}]},)"
      R"({"name":")" +
      escape +
      R"(","type":"buffer","code":"void mainImage(out vec4 o, in vec2 p) { o = vec4(0.5); }","inputs":[],"outputs":[{"id":"XsXGR8","channel":0}]},)"
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
