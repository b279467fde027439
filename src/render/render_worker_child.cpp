#include "render/render_worker_child.h"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <new>

#include "render/outcome_wire.h"
#include "render/request_wire.h"
#include "render/reusable_context.h"

namespace shaderport::render {
namespace {

constexpr int kSocketFd = 3;                         // where the worker keeps its socket
constexpr uint64_t kMaxRequest = uint64_t{1} << 31;  // channel images included

bool ReadExactly(int fd, char* data, size_t size) {
  size_t done = 0;
  while (done < size) {
    const ssize_t n = read(fd, data + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

bool WriteAll(int fd, const char* data, size_t size) {
  size_t done = 0;
  while (done < size) {
    // MSG_NOSIGNAL: a parent gone away ends the worker by exit status, not SIGPIPE.
    const ssize_t n = send(fd, data + done, size - done, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

// Keeps only the socket, at a fixed number: descriptors inherited from the parent's
// other threads (another worker's socket, files being written) must not stay open
// for the worker's whole life, or their owners would never see them close.
int KeepOnlySocket(int socket) {
  if (socket != kSocketFd) {
    dup2(socket, kSocketFd);
    close(socket);
  }
  close_range(kSocketFd + 1, ~0U, 0);
  return kSocketFd;
}

void Sandbox(const WorkerSettings& settings) {
  // Mesa's warnings would interleave with shaderport's output; keep them unless asked.
  const int null_fd = open("/dev/null", O_RDWR);
  if (null_fd >= 0) {
    dup2(null_fd, STDIN_FILENO);
    if (std::getenv("SHADERPORT_RENDER_DEBUG") == nullptr) {
      dup2(null_fd, STDERR_FILENO);
      dup2(null_fd, STDOUT_FILENO);
    }
    if (null_fd > STDERR_FILENO) close(null_fd);
  }
  if (settings.address_space_limit != RLIM_INFINITY) {
    const rlimit limit{settings.address_space_limit, settings.address_space_limit};
    setrlimit(RLIMIT_AS, &limit);
  }
  // llvmpipe without LLVM's IR optimisation passes: they are most of a render's
  // compile time and nearly none of its draw at ShaderToy sizes, and some raymarchers
  // took minutes in them (WtccRB: over 120 s, 0.4 s without). They keep IEEE float
  // semantics, so pictures are the same bytes (measured on 240 corpus passes).
  // A GALLIVM_PERF the user set is kept.
  setenv("GALLIVM_PERF", "nopt", 0);
  if (settings.hermetic || settings.cache_dir.empty()) {
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    setenv("MESA_GLSL_CACHE_DISABLE", "true", 1);
  } else {
    setenv("MESA_SHADER_CACHE_DIR", settings.cache_dir.c_str(), 1);
    setenv("MESA_GLSL_CACHE_DIR", settings.cache_dir.c_str(), 1);
    unsetenv("MESA_SHADER_CACHE_DISABLE");
    unsetenv("MESA_GLSL_CACHE_DISABLE");
  }
}

// One request, one reply; false when the parent closed the socket (retired us).
bool ServeOne(int fd, ReusableContext& context) {
  uint64_t size = 0;
  if (!ReadExactly(fd, reinterpret_cast<char*>(&size), sizeof(size))) return false;
  if (size > kMaxRequest) _exit(kWorkerBadRequestExit);
  std::string bytes(size, '\0');
  if (!ReadExactly(fd, bytes.data(), bytes.size())) _exit(kWorkerBadRequestExit);
  std::optional<RenderRequest> request = DecodeRequest(bytes);
  if (!request) _exit(kWorkerBadRequestExit);
  bytes = {};
  std::string reply;
  reply.resize(sizeof(uint64_t));
  reply += EncodeOutcome(context.Render(*request));
  const uint64_t reply_size = reply.size() - sizeof(uint64_t);
  reply.replace(0, sizeof(uint64_t), reinterpret_cast<const char*>(&reply_size), sizeof(uint64_t));
  if (!WriteAll(fd, reply.data(), reply.size())) _exit(4);
  return true;
}

}  // namespace

void RunWorkerChild(int socket, pid_t parent, const WorkerSettings& settings) {
  // A parent killed outright (SIGKILL, OOM killer) never reaps us: die with it, or
  // a shader spinning in llvmpipe would outlive the run. The parent may already be
  // gone before prctl takes effect.
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(5);
  const int fd = KeepOnlySocket(socket);
  Sandbox(settings);
  int code = 0;
  try {
    ReusableContext context(settings.backend);
    while (ServeOne(fd, context)) {
    }
  } catch (const std::bad_alloc&) {
    code = kWorkerOutOfMemoryExit;  // the address-space limit
  } catch (...) {
    code = 3;
  }
  _exit(code);  // no atexit handlers or static destructors of the parent's state
}

}  // namespace shaderport::render
