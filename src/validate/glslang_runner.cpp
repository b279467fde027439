#include "validate/glslang_runner.h"

#include <fcntl.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <mutex>
#include <vector>

#include "base/large_stack.h"
#include "validate/precise_pass.h"

namespace shaderport::validate {

void InitializeGlslangOnce() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

namespace {

// A crashing child does not need the huge stack: it only has to fail fast.
constexpr size_t kIsolatedStackBytes = size_t{32} << 20;

// Must run on the thread that owns the TShader: glslang's pool allocator is per thread.
void RunOnThisThread(std::span<const GlslangPart> parts, model::Stage stage, int default_version,
                     bool link, GlslangRun& run) {
  const EShLanguage language = stage == model::Stage::kVertex ? EShLangVertex : EShLangFragment;
  std::vector<const char*> texts, names;
  std::vector<int> lengths;
  std::vector<std::string_view> views;
  for (const GlslangPart& part : parts) {
    texts.push_back(part.text.data());
    lengths.push_back(static_cast<int>(part.text.size()));
    names.push_back(part.name.c_str());
    views.push_back(part.text);
  }
  glslang::TShader shader(language);
  shader.setStringsWithLengthsAndNames(texts.data(), lengths.data(), names.data(),
                                       static_cast<int>(texts.size()));
  shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientNone, 0);
  shader.setEnvClient(glslang::EShClientNone, static_cast<glslang::EShTargetClientVersion>(0));
  shader.setEnvTarget(glslang::EShTargetNone, static_cast<glslang::EShTargetLanguageVersion>(0));
  const auto messages = static_cast<EShMessages>(EShMsgCascadingErrors);
  {
    // Validation reads no tree, so glslang's `precise` pass is wasted work when
    // the text cannot use the keyword (precise_pass.h).
    const PrecisePassSkip skip(views);
    run.compiled = shader.parse(GetDefaultResources(), default_version, false, messages);
  }
  run.compile_log = shader.getInfoLog();
  if (link && run.compiled) {
    glslang::TProgram program;
    program.addShader(&shader);
    run.linked = program.link(messages);
    run.link_log = program.getInfoLog();
  }
  run.ran = true;
}

GlslangRun RunWithStack(std::span<const GlslangPart> parts, model::Stage stage, int default_version,
                        bool link, size_t stack_bytes) {
  InitializeGlslangOnce();
  GlslangRun run;
  RunOnLargeStack([&] { RunOnThisThread(parts, stage, default_version, link, run); }, stack_bytes);
  return run;
}

// The same on the calling thread's long-lived large-stack thread: `check` runs
// glslang once a file, and a fresh 256 MiB-stack thread each time costs system
// time (mapping and unmapping the stack, faulting its pages in again).
GlslangRun RunOnLongLivedStack(std::span<const GlslangPart> parts, model::Stage stage,
                               int default_version, bool link) {
  InitializeGlslangOnce();
  GlslangRun run;
  RunOnLongLivedLargeStack([&] { RunOnThisThread(parts, stage, default_version, link, run); });
  return run;
}

void WriteAll(int fd, std::string_view data) {
  while (!data.empty()) {
    const ssize_t n = write(fd, data.data(), data.size());
    if (n <= 0) return;
    data.remove_prefix(static_cast<size_t>(n));
  }
}

// Child -> parent wire format: 3 flag bytes, then both logs each preceded by its size.
std::string Serialize(const GlslangRun& run) {
  std::string out;
  out += run.ran ? '1' : '0';
  out += run.compiled ? '1' : '0';
  out += run.linked ? '1' : '0';
  for (const std::string* log : {&run.compile_log, &run.link_log}) {
    out += std::to_string(log->size()) + '\n' + *log;
  }
  return out;
}

bool Deserialize(std::string_view data, GlslangRun& run) {
  if (data.size() < 3) return false;
  run.ran = data[0] == '1';
  run.compiled = data[1] == '1';
  run.linked = data[2] == '1';
  data.remove_prefix(3);
  for (std::string* log : {&run.compile_log, &run.link_log}) {
    const size_t newline = data.find('\n');
    if (newline == std::string_view::npos) return false;
    size_t size = 0;
    for (char c : data.substr(0, newline)) size = size * 10 + static_cast<size_t>(c - '0');
    data.remove_prefix(newline + 1);
    if (data.size() < size) return false;
    *log = std::string(data.substr(0, size));
    data.remove_prefix(size);
  }
  return true;
}

// Reads until EOF or the deadline; false on timeout.
bool ReadUntilClosed(int fd, std::string& out, int timeout_ms) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  char buffer[65536];
  while (true) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd poll_fd{fd, POLLIN, 0};
    const int ready = poll(&poll_fd, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) return false;
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;
    out.append(buffer, static_cast<size_t>(n));
  }
}

}  // namespace

GlslangRun RunGlslang(std::span<const GlslangPart> parts, model::Stage stage, int default_version,
                      bool link) {
  return RunOnLongLivedStack(parts, stage, default_version, link);
}

namespace {

// One run in a forked child; `hung` is set when it did not finish in time.
GlslangRun RunInChild(std::span<const GlslangPart> parts, model::Stage stage, int default_version,
                      bool link, int timeout_ms, bool& hung) {
  hung = false;
  GlslangRun failed;
  int fds[2];
  // CLOEXEC: no program started later inherits it (forked render workers close
  // every inherited descriptor themselves).
  if (pipe2(fds, O_CLOEXEC) != 0) return failed;
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    return failed;
  }
  if (pid == 0) {
    close(fds[0]);
    WriteAll(fds[1],
             Serialize(RunWithStack(parts, stage, default_version, link, kIsolatedStackBytes)));
    _exit(0);
  }
  close(fds[1]);
  std::string data;
  const bool finished = ReadUntilClosed(fds[0], data, timeout_ms);
  close(fds[0]);
  hung = !finished;
  if (!finished) kill(pid, SIGKILL);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  GlslangRun run;
  const bool clean_exit = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (!finished || !clean_exit || !Deserialize(data, run)) {
    failed.crashed = true;
    return failed;
  }
  return run;
}

}  // namespace

GlslangRun RunGlslangIsolated(std::span<const GlslangPart> parts, model::Stage stage,
                              int default_version, bool link, int timeout_ms) {
  // A child forked while another thread of this process held a lock (the allocator's,
  // say) can wait for it forever, and a loaded machine can pass the time limit: one more
  // try before a hang counts (in a batch of 1,000 files a child failed where the same file
  // alone compiled).
  bool hung = false;
  GlslangRun run = RunInChild(parts, stage, default_version, link, timeout_ms, hung);
  if (hung) run = RunInChild(parts, stage, default_version, link, timeout_ms, hung);
  return run;
}

}  // namespace shaderport::validate
