#include "render/isolated_render.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "render/gl_renderer.h"
#include "render/outcome_wire.h"

// AddressSanitizer reserves terabytes of shadow address space: an RLIMIT_AS would
// kill every sanitized render child, so sanitized builds skip the limit.
#if defined(__SANITIZE_ADDRESS__)
#define SHADERPORT_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SHADERPORT_ASAN 1
#endif
#endif

namespace shaderport::render {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kOutOfMemoryExit = 6;  // the child's exit status after std::bad_alloc

bool WriteAll(int fd, const std::string& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

// The child's RLIMIT_AS: the requested one, but never above the limit the caller
// set (ulimit -v, prlimit), which root could otherwise raise.
rlim_t ChildAddressSpaceLimit(uint64_t requested) {
#ifdef SHADERPORT_ASAN
  (void)requested;
  return RLIM_INFINITY;
#else
  rlimit current{};
  if (getrlimit(RLIMIT_AS, &current) != 0) current.rlim_cur = RLIM_INFINITY;
  return requested > 0 ? std::min<rlim_t>(current.rlim_cur, requested) : current.rlim_cur;
#endif
}

[[noreturn]] void RunChild(int fd, pid_t parent, rlim_t address_space_limit,
                           const RenderRequest& request, const RenderOptions& options,
                           const std::string& cache_dir) {
  // A parent killed outright (SIGKILL, OOM killer) never reaps us: die with it, or
  // a shader spinning in llvmpipe would outlive the run. The parent may already be
  // gone before prctl takes effect.
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(5);
  // Mesa's warnings would interleave with shaderport's output; keep them unless asked.
  if (std::getenv("SHADERPORT_RENDER_DEBUG") == nullptr) {
    const int null_fd = open("/dev/null", O_WRONLY);
    if (null_fd >= 0) {
      dup2(null_fd, STDERR_FILENO);
      dup2(null_fd, STDOUT_FILENO);
      close(null_fd);
    }
  }
  if (address_space_limit != RLIM_INFINITY) {
    const rlimit limit{address_space_limit, address_space_limit};
    setrlimit(RLIMIT_AS, &limit);
  }
  if (options.hermetic || cache_dir.empty()) {
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    setenv("MESA_GLSL_CACHE_DISABLE", "true", 1);
  } else {
    setenv("MESA_SHADER_CACHE_DIR", cache_dir.c_str(), 1);
    setenv("MESA_GLSL_CACHE_DIR", cache_dir.c_str(), 1);
    unsetenv("MESA_SHADER_CACHE_DISABLE");
  }
  int code = 0;
  try {
    const RenderOutcome outcome = RenderInThisProcess(request, options.backend);
    code = WriteAll(fd, EncodeOutcome(outcome)) ? 0 : 4;
  } catch (const std::bad_alloc&) {
    code = kOutOfMemoryExit;  // the address-space limit
  } catch (...) {
    code = 3;
  }
  close(fd);
  _exit(code);  // no atexit handlers or static destructors of the parent's state
}

std::string DescribeExit(int status, rlim_t address_space_limit) {
  const std::string limit =
      address_space_limit != RLIM_INFINITY
          ? " (address-space limit " + std::to_string(address_space_limit >> 20) + " MiB)"
          : "";
  if (WIFEXITED(status) && WEXITSTATUS(status) == kOutOfMemoryExit) {
    return "the render process ran out of memory" + limit;
  }
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    const char* name = sigabbrev_np(signal);
    const bool memory = signal == SIGKILL || signal == SIGSEGV || signal == SIGABRT;
    return std::string("the render process was killed by SIG") + (name ? name : "?") +
           (memory ? ": out of memory" + limit + " or a driver crash?" : "");
  }
  if (WIFEXITED(status)) {
    return "the render process exited with status " + std::to_string(WEXITSTATUS(status)) +
           " without a result";
  }
  return "the render process ended abnormally";
}

}  // namespace

std::string DefaultMesaCacheDir() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0') {
    return std::string(xdg) + "/shaderport/mesa";
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return std::string(home) + "/.cache/shaderport/mesa";
  }
  return {};
}

RenderOutcome RenderIsolated(const RenderRequest& request, const RenderOptions& options) {
  const auto start = Clock::now();
  RenderOutcome failed;
  std::string cache_dir;
  if (!options.hermetic) {
    cache_dir = options.cache_dir.empty() ? DefaultMesaCacheDir() : options.cache_dir;
    std::error_code ignored;
    if (!cache_dir.empty()) std::filesystem::create_directories(cache_dir, ignored);
  }
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    failed.status = RenderStatus::kInternal;
    failed.message = std::string("pipe failed: ") + std::strerror(errno);
    return failed;
  }
  const pid_t parent = getpid();
  const rlim_t address_space_limit = ChildAddressSpaceLimit(options.address_space_limit);
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    failed.status = RenderStatus::kInternal;
    failed.message = std::string("fork failed: ") + std::strerror(errno);
    return failed;
  }
  if (pid == 0) {
    close(fds[0]);
    RunChild(fds[1], parent, address_space_limit, request, options, cache_dir);
  }
  close(fds[1]);

  // Read while waiting: a result larger than the pipe buffer would otherwise block.
  const auto deadline = start + options.timeout;
  const size_t max_bytes = size_t{request.width} * request.height * 16 + (size_t{16} << 20);
  std::string bytes;
  bool timed_out = false;
  bool too_large = false;
  char buffer[65536];
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd poll_fd{fds[0], POLLIN, 0};
    const int ready = poll(&poll_fd, 1, static_cast<int>(std::min<int64_t>(left.count(), 1000)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t n = read(fds[0], buffer, sizeof(buffer));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // EOF: the child closed its end (finished or died)
    bytes.append(buffer, static_cast<size_t>(n));
    if (bytes.size() > max_bytes) {
      too_large = true;
      break;
    }
  }
  close(fds[0]);
  int status = 0;
  if (timed_out || too_large) {
    kill(pid, SIGKILL);
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
  } else {
    // The child _exits right after closing the pipe; bound the wait anyway.
    for (;;) {
      const pid_t done = waitpid(pid, &status, WNOHANG);
      if (done == pid || (done < 0 && errno != EINTR)) break;
      if (Clock::now() > deadline) {
        kill(pid, SIGKILL);
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
        break;
      }
      usleep(1000);
    }
  }
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  if (timed_out) {
    failed.status = RenderStatus::kTimeout;
    failed.message = "the render did not finish within " + std::to_string(options.timeout.count()) +
                     " ms and was killed";
    failed.milliseconds = ms;
    return failed;
  }
  std::optional<RenderOutcome> outcome;
  if (!too_large) outcome = DecodeOutcome(bytes);
  if (!outcome) {
    failed.status = RenderStatus::kCrashed;
    failed.message = too_large ? "the render process sent an oversized result"
                               : DescribeExit(status, address_space_limit);
    failed.milliseconds = ms;
    return failed;
  }
  outcome->milliseconds = ms;
  return std::move(*outcome);
}

}  // namespace shaderport::render
