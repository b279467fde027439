#include "render/render_worker.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <optional>

#include "base/osmesa_library.h"
#include "render/outcome_wire.h"
#include "render/render_worker_child.h"
#include "render/request_wire.h"

namespace shaderport::render {
namespace {

using Clock = std::chrono::steady_clock;

enum class Io : uint8_t { kDone, kClosed, kTimedOut };

// Waits for `events` on `fd` until `deadline`, in slices so that a clock jump or
// EINTR never stretches the wait.
Io WaitFor(int fd, short events, Clock::time_point deadline) {
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) return Io::kTimedOut;
    pollfd poll_fd{fd, events, 0};
    const int ready = poll(&poll_fd, 1, static_cast<int>(std::min<int64_t>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) return Io::kClosed;
    if (ready > 0) return Io::kDone;
  }
}

Io SendAll(int fd, const std::string& bytes, Clock::time_point deadline) {
  size_t done = 0;
  while (done < bytes.size()) {
    if (const Io waited = WaitFor(fd, POLLOUT, deadline); waited != Io::kDone) return waited;
    // MSG_NOSIGNAL: a dead worker is an error to report, not a SIGPIPE for the parent.
    const ssize_t n =
        send(fd, bytes.data() + done, bytes.size() - done, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) return Io::kClosed;
    done += static_cast<size_t>(n);
  }
  return Io::kDone;
}

Io ReceiveExactly(int fd, char* data, size_t size, Clock::time_point deadline) {
  size_t done = 0;
  while (done < size) {
    if (const Io waited = WaitFor(fd, POLLIN, deadline); waited != Io::kDone) return waited;
    const ssize_t n = recv(fd, data + done, size - done, MSG_DONTWAIT);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) return Io::kClosed;  // EOF: the worker died (or exited) mid-render
    done += static_cast<size_t>(n);
  }
  return Io::kDone;
}

std::string DescribeExit(int status, rlim_t address_space_limit) {
  const std::string limit =
      address_space_limit != RLIM_INFINITY
          ? " (address-space limit " + std::to_string(address_space_limit >> 20) + " MiB)"
          : "";
  if (WIFEXITED(status) && WEXITSTATUS(status) == kWorkerOutOfMemoryExit) {
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

RenderOutcome Failed(RenderStatus status, std::string message, Clock::time_point start) {
  RenderOutcome failed;
  failed.status = status;
  failed.message = std::move(message);
  failed.milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  return failed;
}

std::string Framed(std::string payload) {
  const uint64_t size = payload.size();
  std::string frame(reinterpret_cast<const char*>(&size), sizeof(size));
  return frame + payload;
}

}  // namespace

RenderWorker::RenderWorker(WorkerSettings settings)
    : settings_(std::move(settings)), debug_(std::getenv("SHADERPORT_RENDER_DEBUG") != nullptr) {}

RenderWorker::~RenderWorker() {
  if (pid_ > 0) Retire();
}

bool RenderWorker::Start(std::string& error) {
  // Job threads start workers concurrently: one at a time, so that a worker's end of
  // the socket pair is in exactly two processes (a concurrent fork would copy it into
  // another worker, where it stays open until that worker's KeepOnlySocket).
  static std::mutex fork_mutex;
  const std::lock_guard lock(fork_mutex);
  // OSMesa is loaded on first use (base/osmesa_library.h): load it here, before the
  // fork, so that workers inherit it loaded as when it was linked, rather than each
  // running the dynamic loader in a child of a multi-threaded process. A failure is
  // reported by the worker's backend.
  std::string ignored;
  LoadOsMesa(ignored);
  int fds[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) {
    error = std::string("socketpair failed: ") + std::strerror(errno);
    return false;
  }
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    error = std::string("fork failed: ") + std::strerror(errno);
    close(fds[0]);
    close(fds[1]);
    return false;
  }
  if (pid == 0) {
    close(fds[0]);
    RunWorkerChild(fds[1], parent, settings_);
  }
  close(fds[1]);
  pid_ = pid;
  socket_ = fds[0];
  renders_ = 0;
  return true;
}

int RenderWorker::ReapBy(Clock::time_point deadline) {
  int status = 0;
  for (;;) {
    const pid_t done = waitpid(pid_, &status, WNOHANG);
    if (done == pid_ || (done < 0 && errno != EINTR)) break;
    if (Clock::now() > deadline) {
      kill(pid_, SIGKILL);
      while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
      }
      break;
    }
    usleep(500);
  }
  close(socket_);
  socket_ = -1;
  pid_ = -1;
  return status;
}

int RenderWorker::KillAndReap() {
  kill(pid_, SIGKILL);
  return ReapBy(Clock::now() + std::chrono::hours(1));  // SIGKILL cannot be ignored
}

void RenderWorker::Retire() {
  // An idle worker _exits on EOF: no signal needed, and no half-written cache entry.
  shutdown(socket_, SHUT_WR);
  ReapBy(Clock::now() + std::chrono::seconds(2));
}

RenderOutcome RenderWorker::Render(const RenderRequest& request,
                                   std::chrono::milliseconds timeout) {
  RenderOutcome outcome = Exchange(request, timeout);
  if (debug_) {
    // One line per render, for bench/render_batch_bench.sh and for debugging.
    std::fprintf(stderr, "shaderport render worker: status %d in %.1f ms\n",
                 static_cast<int>(outcome.status), outcome.milliseconds);
  }
  return outcome;
}

RenderOutcome RenderWorker::Exchange(const RenderRequest& request,
                                     std::chrono::milliseconds timeout) {
  const auto start = Clock::now();
  const auto deadline = start + timeout;
  const std::string frame = Framed(EncodeRequest(request));
  const std::string timed_out_message =
      "the render did not finish within " + std::to_string(timeout.count()) + " ms and was killed";
  // An idle worker can die from outside (OOM killer, a stray kill): then one retry
  // on a fresh worker, whose own death is the request's fault.
  for (int attempt = 0;; ++attempt) {
    const bool fresh = pid_ < 0;
    std::string error;
    if (fresh && !Start(error)) return Failed(RenderStatus::kInternal, error, start);
    const Io sent = SendAll(socket_, frame, deadline);
    if (sent == Io::kDone) break;
    if (sent == Io::kTimedOut) {
      KillAndReap();
      return Failed(RenderStatus::kTimeout, timed_out_message, start);
    }
    const int status = KillAndReap();
    if (fresh || attempt > 0) {
      return Failed(RenderStatus::kCrashed, DescribeExit(status, settings_.address_space_limit),
                    start);
    }
  }

  const uint64_t max_bytes = uint64_t{request.width} * request.height * 16 + (uint64_t{16} << 20);
  uint64_t size = 0;
  Io received = ReceiveExactly(socket_, reinterpret_cast<char*>(&size), sizeof(size), deadline);
  std::string bytes;
  if (received == Io::kDone && size > max_bytes) {
    KillAndReap();
    return Failed(RenderStatus::kCrashed, "the render process sent an oversized result", start);
  }
  if (received == Io::kDone) {
    bytes.resize(size);
    received = ReceiveExactly(socket_, bytes.data(), bytes.size(), deadline);
  }
  if (received == Io::kTimedOut) {
    KillAndReap();
    return Failed(RenderStatus::kTimeout, timed_out_message, start);
  }
  if (received == Io::kClosed) {
    // The worker ends right after its socket closes; bound the wait anyway.
    const int status = ReapBy(deadline);
    return Failed(RenderStatus::kCrashed, DescribeExit(status, settings_.address_space_limit),
                  start);
  }
  std::optional<RenderOutcome> outcome = DecodeOutcome(bytes);
  if (!outcome) {
    KillAndReap();
    return Failed(RenderStatus::kCrashed, "the render process sent a malformed result", start);
  }
  outcome->milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  if (++renders_ >= settings_.max_renders) Retire();
  return std::move(*outcome);
}

}  // namespace shaderport::render
