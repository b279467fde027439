// The persistent render worker through the real binary (docs/render.md, Isolation):
// in one `check --render` batch a timeout and an out-of-memory render cost only
// themselves, pictures are byte-identical whatever the worker reuse and -j, and no
// worker serving a batch outlives a SIGKILLed parent.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
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

// A picture with no finding, different for each `k`.
std::string GoodShader(int k) {
  return "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
         "  vec2 uv = fragCoord / iResolution.xy;\n"
         "  fragColor = vec4(uv, 0.5 + 0.5 * sin(" +
         std::to_string(k + 1) + ".0 * uv.x), 1.0);\n}\n";
}

std::vector<std::string> LinesAbout(const std::string& text, const std::string& file) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.find(file) != std::string::npos) lines.push_back(line);
  }
  return lines;
}

std::string ReadFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

class RenderWorkerCliTest : public ::testing::Test {
 protected:
  BoundedRun Run(const std::vector<std::string>& args, BoundedRunOptions options = {}) {
    options.directory = project_.Root();
    // check --render uses the user's Mesa cache: keep it inside the project.
    options.environment.push_back("XDG_CACHE_HOME=" + (project_.Root() / "cache").string());
    return RunBounded(args, options);
  }
  TempProject project_{"render-worker"};
};

TEST_F(RenderWorkerCliTest, TimeoutAndOutOfMemoryCostOnlyTheirOwnRender) {
  project_.Write("shaders/a_good.glsl", GoodShader(0));
  project_.Write("shaders/b_spin.glsl", kSpinningShader);
  project_.Write("shaders/c_good.glsl", GoodShader(1));
  project_.Write("shaders/d_huge.glsl", kHugeArrayShader);
  project_.Write("shaders/e_good.glsl", GoodShader(2));
  BoundedRunOptions options;
  options.time_limit = std::chrono::seconds(40);
  if (!kSanitizedBuild) options.address_space = rlim_t{1} << 30;
  const BoundedRun check = Run({"check", "--no-cache", "--render", "--render-size", "128",
                                "--render-timeout", "1", "-j1", "shaders"},
                               options);
  EXPECT_EQ(check.exit_code, 1) << check.Printed();
  const std::vector<std::string> spin = LinesAbout(check.out, "b_spin.glsl");
  ASSERT_EQ(spin.size(), 1u) << check.Printed();
  EXPECT_NE(spin[0].find("did not finish within 1000 ms and was killed [render/timeout]"),
            std::string::npos)
      << spin[0];
  if (!kSanitizedBuild) {
    const std::vector<std::string> huge = LinesAbout(check.out, "d_huge.glsl");
    ASSERT_EQ(huge.size(), 1u) << check.Printed();
    EXPECT_NE(huge[0].find("[render/crashed]"), std::string::npos) << huge[0];
    EXPECT_NE(huge[0].find("out of memory"), std::string::npos) << huge[0];
    EXPECT_NE(huge[0].find("address-space limit 1024 MiB"), std::string::npos) << huge[0];
  }
  for (const char* good : {"a_good.glsl", "c_good.glsl", "e_good.glsl"}) {
    EXPECT_TRUE(LinesAbout(check.out, good).empty()) << good << "\n" << check.Printed();
  }
  EXPECT_LT(check.seconds, 30) << "the limits, not the bound, end the bad renders";
  // Not hermetic: the worker uses (and fills) Mesa's cache under XDG_CACHE_HOME.
  const fs::path mesa_cache = project_.Root() / "cache/shaderport/mesa";
  EXPECT_TRUE(fs::is_directory(mesa_cache) && !fs::is_empty(mesa_cache));
}

// Shaders whose pictures and findings differ: ShaderToy passes, a flat colour
// (render/single-colour), one that does not compile (not drawn), WebGL1 (drawn
// through its port) and WebGL2.
void WriteMixedShaders(TempProject& project) {
  for (int k = 0; k < 6; ++k) {
    project.Write("shaders/s" + std::to_string(k) + ".glsl", GoodShader(k));
  }
  project.Write("shaders/flat.glsl",
                "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.25, 0.5, 0.75, 1.0); }\n");
  project.Write("shaders/broken.glsl", "void mainImage(out vec4 c, in vec2 p) { c = 1.0; }\n");
  project.Write("shaders/webgl1.frag",
                "precision mediump float;\nuniform vec2 resolution;\n"
                "void main() { gl_FragColor = vec4(gl_FragCoord.xy / resolution, 0.3, 1.0); }\n");
  project.Write("shaders/webgl2.frag",
                "#version 300 es\nprecision highp float;\nout vec4 color;\n"
                "void main() { color = vec4(fract(gl_FragCoord.xy / 8.0), 0.6, 1.0); }\n");
}

struct Variant {
  std::string name;
  std::string jobs;
  std::string worker_renders;
};

// One worker for all, a fresh process per render, two jobs with a worker each, and
// two jobs whose workers are replaced every second render.
const std::vector<Variant> kVariants = {{"worker-j1", "1", "200"},
                                        {"fresh-j1", "1", "1"},
                                        {"worker-j2", "2", "200"},
                                        {"short-lived-j2", "2", "2"}};

// The same pictures (embedded PNGs) and findings whatever the worker reuse and -j:
// each job thread draws its own files with its own worker.
TEST_F(RenderWorkerCliTest, ReportIsByteIdenticalWhateverTheWorkerReuseAndJobs) {
  WriteMixedShaders(project_);
  std::string first;
  for (const Variant& variant : kVariants) {
    BoundedRunOptions options;
    options.time_limit = std::chrono::seconds(60);
    options.environment.push_back("SHADERPORT_RENDER_WORKER_RENDERS=" + variant.worker_renders);
    const std::string html = variant.name + ".html";
    const BoundedRun report =
        Run({"report", "--hermetic", "-j", variant.jobs, "--html", html, "shaders"}, options);
    ASSERT_FALSE(report.timed_out) << variant.name;
    const std::string text = ReadFile(project_.Root() / html);
    ASSERT_NE(text.find("data:image/png;base64,"), std::string::npos) << variant.name;
    if (first.empty()) {
      first = text;
    } else {
      EXPECT_TRUE(text == first) << variant.name << " differs from " << kVariants[0].name;
    }
  }
}

// `check --render` findings, in JSON, the same way.
TEST_F(RenderWorkerCliTest, CheckRenderJsonIsByteIdenticalWhateverTheWorkerReuseAndJobs) {
  WriteMixedShaders(project_);
  std::string first;
  for (const Variant& variant : kVariants) {
    BoundedRunOptions options;
    options.time_limit = std::chrono::seconds(60);
    options.environment.push_back("SHADERPORT_RENDER_WORKER_RENDERS=" + variant.worker_renders);
    const BoundedRun check =
        Run({"check", "--no-cache", "--render", "--format", "json", "-j", variant.jobs, "shaders"},
            options);
    ASSERT_FALSE(check.timed_out) << variant.name;
    EXPECT_EQ(check.exit_code, 1) << variant.name << "\n" << check.Printed();  // broken.glsl
    ASSERT_NE(check.out.find("render/single-colour"), std::string::npos) << check.Printed();
    if (first.empty()) {
      first = check.out;
    } else {
      EXPECT_EQ(check.out, first) << variant.name << " differs from " << kVariants[0].name;
    }
  }
}

// A worker between renders of a parallel check's batch dies with the parent too.
TEST_F(RenderWorkerCliTest, NoWorkerOfACheckBatchOutlivesAKilledParent) {
  project_.Write("a_good.glsl", GoodShader(0));
  project_.Write("b_spin.glsl", kSpinningShader);
  // A batch: the worker serves the first file and is drawing the second when the
  // parent dies.
  const KilledParentRun run =
      RunAndKillParent({"check", "--no-cache", "--render", "--render-size", "128",
                        "--render-timeout", "60", "-j", "2", "a_good.glsl", "b_spin.glsl"},
                       project_.Root(), {"XDG_CACHE_HOME=" + (project_.Root() / "cache").string()},
                       std::chrono::milliseconds(500));
  EXPECT_TRUE(run.render_started) << "the worker never started";
  EXPECT_TRUE(run.survivors.empty()) << "a render worker survived its parent";
}

}  // namespace
}  // namespace shaderport::testing
