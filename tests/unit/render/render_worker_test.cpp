// The persistent render worker (render/render_worker.h): many renders in one
// process, each identical to a render in a process of its own; a timeout, a crash
// or an outside kill costs only that render, and the next one gets a new worker.
#include "render/render_worker.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>
#include <vector>

#include "render/isolated_render.h"
#include "render_test_support.h"

namespace shaderport::render {
namespace {

using testing::BufferPassReading;
using testing::FastOptions;
using testing::FragmentRequest;
using testing::kGradient;
using testing::ShaderToyText;

const char* const kRings =
    "void mainImage(out vec4 c, in vec2 p) {\n"
    "  float r = length(p - iResolution.xy * 0.5);\n"
    "  c = vec4(fract(r * 0.1), sin(r), cos(r * 0.3), 1.0);\n"
    "}\n";

const char* const kCompileError = "void mainImage(out vec4 c, in vec2 p) { vec3 v = 1.0; }\n";

// llvmpipe caps loops at 65535 iterations: the body must be heavy enough that the
// capped loop still takes far longer than the timeout.
const char* const kSpinning =
    "#define S(x) x = sin(x) * cos(x * 1.1) + 0.1;\n"
    "#define S8(x) S(x) S(x) S(x) S(x) S(x) S(x) S(x) S(x)\n"
    "void mainImage(out vec4 c, in vec2 p) {\n"
    "  float x = p.x;\n"
    "  for (;;) { S8(x) S8(x) S8(x) S8(x) S8(x) S8(x) S8(x) S8(x) if (x > 1e9) break; }\n"
    "  c = vec4(x);\n}\n";

// An 800 MB local array: Mesa's compiler allocates far past a 1 GiB limit.
const char* const kHugeArray =
    "void mainImage(out vec4 c, in vec2 p) {\n"
    "  float a[200000000];\n"
    "  for (int i = 0; i < 200000000; i++) a[i] = float(i);\n"
    "  c = vec4(a[int(p.x)], 0.0, 0.0, 1.0);\n}\n";

WorkerSettings Hermetic() {
  WorkerSettings settings;
  settings.hermetic = true;
  settings.address_space_limit = rlim_t{4} << 30;
#if defined(__SANITIZE_ADDRESS__)
  settings.address_space_limit = RLIM_INFINITY;
#endif
  return settings;
}

void ExpectSameOutcome(const RenderOutcome& a, const RenderOutcome& b) {
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.message, b.message);
  EXPECT_EQ(a.vertex_log, b.vertex_log);
  EXPECT_EQ(a.fragment_log, b.fragment_log);
  EXPECT_EQ(a.link_log, b.link_log);
  EXPECT_EQ(a.gl_errors, b.gl_errors);
  EXPECT_EQ(a.max_loop_iterations, b.max_loop_iterations);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  // Bitwise, so NaN pixels compare equal; memcmp must not see the null data of empty vectors.
  if (!a.pixels.empty()) {
    EXPECT_EQ(0, std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)));
  }
}

constexpr std::chrono::milliseconds kTimeout{10'000};

TEST(RenderWorker, ServesSeveralRendersIdenticalToFreshProcesses) {
  const std::vector<RenderRequest> requests = {
      FragmentRequest(ShaderToyText(kGradient)), FragmentRequest(ShaderToyText(kRings), 48),
      FragmentRequest(ShaderToyText(kCompileError)), FragmentRequest(ShaderToyText(kGradient))};
  RenderWorker worker(Hermetic());
  pid_t pid = -1;
  for (const RenderRequest& request : requests) {
    const RenderOutcome served = worker.Render(request, kTimeout);
    if (pid == -1) pid = worker.Pid();
    EXPECT_EQ(worker.Pid(), pid) << "one process serves the whole batch";
    ExpectSameOutcome(served, RenderInFreshProcess(request, FastOptions()));
  }
  EXPECT_EQ(worker.Render(requests[1], kTimeout).status, RenderStatus::kOk);
  EXPECT_EQ(worker.Pid(), pid);
}

// The worker keeps one GL context for the batch and resets it between renders: each
// request below leaves state a fresh context does not have (buffer targets and
// mipmaps, textures of every kind with their samplers, a mesh with its vertex array
// and depth test), and every render after it must still equal a fresh process's.
TEST(RenderWorker, OneContextForTheBatchLeavesNoStateBehind) {
  RenderRequest multipass = FragmentRequest(ShaderToyText(
      "void mainImage(out vec4 c, in vec2 p) {\n"
      "  c = vec4(texelFetch(iChannel0, ivec2(p), 0).r, textureLod(iChannel0, p / 64.0, 2.0).g,"
      " 0.5, 1.0);\n}\n"));
  multipass.buffer_passes = {BufferPassReading(
      0, 0,
      "void mainImage(out vec4 c, in vec2 p) {\n"
      "  c = texelFetch(iChannel0, ivec2(p), 0) + vec4(0.25, p.x / 64.0, 0.0, 0.0);\n}\n")};
  multipass.channel_buffers = {0, -1, -1, -1};
  multipass.frames = 2;
  const RenderRequest channels = FragmentRequest(
      "#version 300 es\nprecision highp float;\n"
      "uniform samplerCube iChannel0;\nuniform highp sampler3D iChannel1;\n"
      "uniform sampler2D iChannel2;\nuniform vec3 iResolution;\nout vec4 o;\n"
      "void main() {\n  vec2 uv = gl_FragCoord.xy / iResolution.xy;\n"
      "  vec3 d = normalize(vec3(uv * 2.0 - 1.0, 0.6));\n"
      "  o = vec4(texture(iChannel0, d).r, texture(iChannel1, vec3(uv, 0.3)).g,\n"
      "           texture(iChannel2, uv).b, 1.0);\n}\n");
  RenderRequest mesh;
  mesh.vertex_source =
      "#version 300 es\nin vec3 Vertex;\nin vec3 Normal;\n"
      "uniform mat4 ProjectionMatrix;\nuniform mat4 ViewMatrix;\nuniform mat4 ModelMatrix;\n"
      "out vec3 vNormal;\nvoid main() {\n  vNormal = Normal;\n"
      "  gl_Position = ProjectionMatrix * ViewMatrix * ModelMatrix * vec4(Vertex, 1.0);\n}\n";
  mesh.fragment_source =
      "#version 300 es\nprecision highp float;\nin vec3 vNormal;\nout vec4 o;\n"
      "void main() { o = vec4(vNormal * 0.5 + 0.5, 1.0); }\n";
  const std::vector<RenderRequest> requests = {
      multipass, FragmentRequest(ShaderToyText(kGradient)),
      channels,  FragmentRequest(ShaderToyText(kRings), 48),
      mesh,      FragmentRequest(ShaderToyText(kGradient)),
      multipass, FragmentRequest(ShaderToyText(kCompileError)),
      channels};
  RenderWorker worker(Hermetic());
  for (size_t i = 0; i < requests.size(); ++i) {
    SCOPED_TRACE(i);
    const RenderOutcome served = worker.Render(requests[i], kTimeout);
    if (i != 7) {
      EXPECT_EQ(served.status, RenderStatus::kOk) << served.fragment_log;
    }
    ExpectSameOutcome(served, RenderInFreshProcess(requests[i], FastOptions()));
  }
}

// What a render makes is deleted before the next: 16 renders of 1024x1024 with four
// buffers (ten 16 MiB float targets each) would pass a 2 GiB address space otherwise.
TEST(RenderWorker, ABatchOfLargeRendersStaysWithinTheAddressSpaceLimit) {
  RenderRequest request =
      FragmentRequest(ShaderToyText("void mainImage(out vec4 c, in vec2 p) {\n"
                                    "  c = texelFetch(iChannel0, ivec2(p), 0) + vec4(0.5);\n}\n"),
                      1024);
  for (int k = 0; k < 4; ++k) {
    request.buffer_passes.push_back(BufferPassReading(
        k, k == 0 ? 3 : k - 1,
        "void mainImage(out vec4 c, in vec2 p) {\n"
        "  c = texelFetch(iChannel0, ivec2(p), 0) * 0.5 + vec4(p / 1024.0, 0.0, 1.0);\n}\n"));
  }
  request.channel_buffers = {3, -1, -1, -1};
  WorkerSettings settings = Hermetic();
#if !defined(__SANITIZE_ADDRESS__)
  settings.address_space_limit = rlim_t{2} << 30;
#endif
  RenderWorker worker(settings);
  for (int i = 0; i < 16; ++i) {
    const RenderOutcome outcome = worker.Render(request, kTimeout);
    ASSERT_EQ(outcome.status, RenderStatus::kOk) << i << ": " << outcome.message;
  }
}

TEST(RenderWorker, TimeoutKillsOnlyThatRender) {
  RenderWorker worker(Hermetic());
  ASSERT_EQ(worker.Render(FragmentRequest(ShaderToyText(kGradient)), kTimeout).status,
            RenderStatus::kOk);
  const pid_t first = worker.Pid();
  const auto start = std::chrono::steady_clock::now();
  const RenderOutcome spun =
      worker.Render(FragmentRequest(ShaderToyText(kSpinning)), std::chrono::milliseconds(1500));
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(3000));
  EXPECT_EQ(spun.status, RenderStatus::kTimeout);
  EXPECT_EQ(spun.message, "the render did not finish within 1500 ms and was killed");
  EXPECT_EQ(worker.Pid(), -1) << "the killed worker is reaped at once";
  EXPECT_EQ(waitpid(first, nullptr, WNOHANG), -1);
  const RenderOutcome next = worker.Render(FragmentRequest(ShaderToyText(kRings)), kTimeout);
  EXPECT_EQ(next.status, RenderStatus::kOk) << next.message;
  EXPECT_NE(worker.Pid(), first);
}

TEST(RenderWorker, OutOfMemoryIsReportedAndTheBatchContinues) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "sanitized builds render without an address-space limit";
#endif
  WorkerSettings settings = Hermetic();
  settings.address_space_limit = rlim_t{1} << 30;
  RenderWorker worker(settings);
  ASSERT_EQ(worker.Render(FragmentRequest(ShaderToyText(kGradient)), kTimeout).status,
            RenderStatus::kOk);
  const RenderOutcome huge = worker.Render(FragmentRequest(ShaderToyText(kHugeArray)), kTimeout);
  EXPECT_EQ(huge.status, RenderStatus::kCrashed);
  EXPECT_NE(huge.message.find("out of memory"), std::string::npos) << huge.message;
  EXPECT_NE(huge.message.find("(address-space limit 1024 MiB)"), std::string::npos) << huge.message;
  const RenderOutcome next = worker.Render(FragmentRequest(ShaderToyText(kGradient)), kTimeout);
  EXPECT_EQ(next.status, RenderStatus::kOk) << next.message;
}

TEST(RenderWorker, AWorkerKilledWhileIdleIsReplaced) {
  RenderWorker worker(Hermetic());
  const RenderRequest request = FragmentRequest(ShaderToyText(kGradient));
  ASSERT_EQ(worker.Render(request, kTimeout).status, RenderStatus::kOk);
  const pid_t first = worker.Pid();
  ASSERT_EQ(kill(first, SIGKILL), 0);
  // Dead before the next request (as after an OOM kill), not dying during it; left
  // for the worker handle to reap.
  siginfo_t info{};
  ASSERT_EQ(waitid(P_PID, static_cast<id_t>(first), &info, WEXITED | WNOWAIT), 0);
  const RenderOutcome next = worker.Render(request, kTimeout);
  EXPECT_EQ(next.status, RenderStatus::kOk) << next.message;
  EXPECT_NE(worker.Pid(), first);
}

TEST(RenderWorker, RetiredAfterMaxRendersAndReaped) {
  WorkerSettings settings = Hermetic();
  settings.max_renders = 2;
  RenderWorker worker(settings);
  const RenderRequest request = FragmentRequest(ShaderToyText(kGradient));
  ASSERT_EQ(worker.Render(request, kTimeout).status, RenderStatus::kOk);
  const pid_t first = worker.Pid();
  ASSERT_EQ(worker.Render(request, kTimeout).status, RenderStatus::kOk);
  EXPECT_EQ(worker.Pid(), -1);
  EXPECT_EQ(waitpid(first, nullptr, WNOHANG), -1) << "retired and reaped, not a zombie";
  ASSERT_EQ(worker.Render(request, kTimeout).status, RenderStatus::kOk);
  EXPECT_NE(worker.Pid(), first);
}

TEST(RenderWorker, DestroyingTheHandleEndsTheProcess) {
  pid_t pid = -1;
  {
    RenderWorker worker(Hermetic());
    ASSERT_EQ(worker.Render(FragmentRequest(ShaderToyText(kGradient)), kTimeout).status,
              RenderStatus::kOk);
    pid = worker.Pid();
  }
  EXPECT_EQ(kill(pid, 0), -1) << "no process left behind";
}

// Live child processes of this process (any thread's).
std::set<pid_t> Children() {
  std::set<pid_t> children;
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream stat(entry.path() / "stat");
    const std::string text((std::istreambuf_iterator<char>(stat)), {});
    const size_t close = text.rfind(')');
    if (close == std::string::npos || close + 4 >= text.size()) continue;
    // ") S PPID ...": state, then the parent's pid.
    if (std::stoi(text.substr(close + 4)) == ::getpid()) children.insert(std::stoi(name));
  }
  return children;
}

// Each thread has its own worker (RenderIsolated); pictures do not depend on which
// thread or worker drew them, and a thread's worker ends with the thread.
TEST(RenderWorker, ThreadsGetAWorkerEachWithIdenticalPictures) {
  if (ParallelRenderJobs(2) < 2) {
    GTEST_SKIP() << "sanitized builds render on one thread (render/isolated_render.h)";
  }
  const std::vector<RenderRequest> requests = {FragmentRequest(ShaderToyText(kGradient)),
                                               FragmentRequest(ShaderToyText(kRings)),
                                               FragmentRequest(ShaderToyText(kCompileError))};
  const std::set<pid_t> before = Children();
  std::vector<std::vector<RenderOutcome>> results(2);
  {
    std::vector<std::jthread> threads;
    for (auto& result : results) {
      threads.emplace_back([&] {
        for (const RenderRequest& request : requests) {
          result.push_back(RenderIsolated(request, FastOptions()));
        }
      });
    }
  }
  EXPECT_EQ(Children(), before) << "a thread's worker outlived the thread";
  ASSERT_EQ(results[0].size(), requests.size());
  ASSERT_EQ(results[1].size(), requests.size());
  for (size_t i = 0; i < requests.size(); ++i) {
    ExpectSameOutcome(results[0][i], results[1][i]);
    ExpectSameOutcome(results[0][i], RenderIsolated(requests[i], FastOptions()));
  }
}

}  // namespace
}  // namespace shaderport::render
