// What the render sandbox and render worker CLI tests share: shaders that only a
// timeout or the memory limit ends, and a run of the binary whose parent is
// SIGKILLed while its render process draws, reporting what survived.
#pragma once

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "golden.h"

namespace shaderport::testing {

// Heavy work in a loop llvmpipe caps at 65,535 iterations per pixel: minutes of
// drawing at 128x128, so only the timeout ends it.
inline constexpr const char* kSpinningShader =
    "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
    "  vec4 x = vec4(fragCoord, 0.0, 1.0);\n"
    "  for (int i = 0; i < 1000000; i++) {\n"
    "    x = sin(x * 1.0001 + cos(x.yzwx)) + exp(-abs(x.zwxy)) * tan(x.wxyz);\n"
    "    x = sin(x * 1.0001 + cos(x.yzwx)) + exp(-abs(x.zwxy)) * tan(x.wxyz);\n"
    "  }\n"
    "  fragColor = x;\n"
    "}\n";

// An 800 MB local array: Mesa's compiler and llvmpipe allocate far past 1 GiB.
// Browsers reject an array this large (webgl/variable-size); the suppression lets
// `check --render` draw it anyway, so that its render runs out of memory.
inline constexpr const char* kHugeArrayShader =
    "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
    "  // shaderport-ignore-next-line(webgl/variable-size)\n"
    "  float a[200000000];\n"
    "  for (int i = 0; i < 200000000; i++) a[i] = float(i);\n"
    "  fragColor = vec4(a[int(fragCoord.x)], 0.0, 0.0, 1.0);\n"
    "}\n";

// Pids of live (not zombie) processes whose environment holds `marker`.
inline std::set<pid_t> ProcessesWithMarker(const std::string& marker) {
  std::set<pid_t> found;
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    if (ReadWholeFile(entry.path() / "environ").find(marker) == std::string::npos) continue;
    const std::string stat = ReadWholeFile(entry.path() / "stat");
    const size_t close = stat.rfind(')');
    if (close != std::string::npos && close + 2 < stat.size() && stat[close + 2] == 'Z') continue;
    found.insert(static_cast<pid_t>(std::stoi(name)));
  }
  return found;
}

struct KilledParentRun {
  bool render_started = false;  // a second process carried the marker
  std::set<pid_t> survivors;    // processes left 5 s after the parent's SIGKILL
};

// Runs shaderport with `args` in `directory` (plus `environment` NAME=VALUE
// entries), waits until a render process exists, lets it draw for `drawing`,
// SIGKILLs the parent and reports who is left (and kills them).
inline KilledParentRun RunAndKillParent(std::vector<std::string> args,
                                        const std::filesystem::path& directory,
                                        std::vector<std::string> environment,
                                        std::chrono::milliseconds drawing) {
  using Clock = std::chrono::steady_clock;
  const std::string marker = "SHADERPORT_KILLED_PARENT_MARKER=" + std::to_string(::getpid()) + "-" +
                             std::to_string(Clock::now().time_since_epoch().count());
  environment.push_back(marker);
  args.insert(args.begin(), SHADERPORT_BINARY);
  std::vector<char*> argv;
  for (std::string& word : args) argv.push_back(word.data());
  argv.push_back(nullptr);
  const std::string where = directory.string();
  const pid_t parent = ::fork();
  if (parent < 0) return {};
  if (parent == 0) {
    if (::chdir(where.c_str()) != 0) ::_exit(126);
    for (std::string& entry : environment) ::putenv(entry.data());
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  KilledParentRun run;
  const auto deadline = Clock::now() + std::chrono::seconds(30);
  while (Clock::now() < deadline && !run.render_started) {
    run.render_started = ProcessesWithMarker(marker).size() >= 2;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::this_thread::sleep_for(drawing);
  ::kill(parent, SIGKILL);
  int status = 0;
  ::waitpid(parent, &status, 0);
  const auto gone_by = Clock::now() + std::chrono::seconds(5);
  while (!ProcessesWithMarker(marker).empty() && Clock::now() < gone_by) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  run.survivors = ProcessesWithMarker(marker);
  for (const pid_t pid : run.survivors) ::kill(pid, SIGKILL);
  return run;
}

}  // namespace shaderport::testing
