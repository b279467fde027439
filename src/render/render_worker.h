// A persistent render process: forked before any GL context exists in the parent
// (the parent never creates one), it serves many requests over a socket so that
// Mesa's one-time start-up (driver load, llvmpipe screen, LLVM, shader cache index)
// is paid once instead of per render. It is replaced after a timeout (SIGKILL and
// reap), a crash, a malformed or oversized reply, and after `max_renders` renders
// to bound leaks. Not thread-safe: one worker per calling thread (isolated_render).
#pragma once

#include <sys/resource.h>
#include <sys/types.h>

#include <chrono>
#include <string>

#include "render/render_request.h"

namespace shaderport::render {

// What a worker process is fixed to: Mesa reads its cache settings from the
// environment once per process, so requests that differ here need another worker.
struct WorkerSettings {
  BackendKind backend = DefaultBackend();
  bool hermetic = false;  // MESA_SHADER_CACHE_DISABLE
  std::string cache_dir;  // used when not hermetic; empty disables the cache too
  rlim_t address_space_limit = RLIM_INFINITY;
  int max_renders = 200;  // then the worker is retired and the next request forks anew
  bool operator==(const WorkerSettings&) const = default;
};

class RenderWorker {
 public:
  explicit RenderWorker(WorkerSettings settings);
  ~RenderWorker();
  RenderWorker(const RenderWorker&) = delete;
  RenderWorker& operator=(const RenderWorker&) = delete;

  const WorkerSettings& Settings() const { return settings_; }
  // Never throws and never leaves a process running past `timeout` (which counts
  // from the call, including the fork when a new worker is needed).
  RenderOutcome Render(const RenderRequest& request, std::chrono::milliseconds timeout);
  pid_t Pid() const { return pid_; }  // -1 when no worker is running

 private:
  RenderOutcome Exchange(const RenderRequest& request, std::chrono::milliseconds timeout);
  bool Start(std::string& error);
  void Retire();      // idle worker: close its socket, let it exit, reap
  int KillAndReap();  // busy or misbehaving worker; returns the wait status
  int ReapBy(std::chrono::steady_clock::time_point deadline);  // then SIGKILL

  WorkerSettings settings_;
  pid_t pid_ = -1;
  int socket_ = -1;
  int renders_ = 0;
  bool debug_ = false;  // SHADERPORT_RENDER_DEBUG: log each render's time to stderr
};

}  // namespace shaderport::render
