#include "render/isolated_render.h"

#include <sys/resource.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "render/render_worker.h"

// AddressSanitizer reserves terabytes of shadow address space: an RLIMIT_AS would
// kill every sanitized render process, so sanitized builds skip the limit.
#if defined(__SANITIZE_ADDRESS__)
#define SHADERPORT_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SHADERPORT_ASAN 1
#endif
#endif

namespace shaderport::render {
namespace {

constexpr int kDefaultWorkerRenders = 200;  // bounds what Mesa leaks per process

// The worker's RLIMIT_AS: the requested one, but never above the limit the caller
// set (ulimit -v, prlimit), which root could otherwise raise.
rlim_t WorkerAddressSpaceLimit(uint64_t requested) {
#ifdef SHADERPORT_ASAN
  (void)requested;
  return RLIM_INFINITY;
#else
  rlimit current{};
  if (getrlimit(RLIMIT_AS, &current) != 0) current.rlim_cur = RLIM_INFINITY;
  return requested > 0 ? std::min<rlim_t>(current.rlim_cur, requested) : current.rlim_cur;
#endif
}

int WorkerRenders() {
  const char* text = std::getenv("SHADERPORT_RENDER_WORKER_RENDERS");
  if (text == nullptr || *text == '\0') return kDefaultWorkerRenders;
  return std::clamp(std::atoi(text), 1, 1'000'000);
}

WorkerSettings SettingsFor(const RenderOptions& options) {
  WorkerSettings settings;
  settings.backend = options.backend;
  settings.hermetic = options.hermetic;
  if (!options.hermetic) {
    settings.cache_dir = options.cache_dir.empty() ? DefaultMesaCacheDir() : options.cache_dir;
    std::error_code ignored;
    if (!settings.cache_dir.empty())
      std::filesystem::create_directories(settings.cache_dir, ignored);
  }
  settings.address_space_limit = WorkerAddressSpaceLimit(options.address_space_limit);
  settings.max_renders = WorkerRenders();
  return settings;
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
  // One worker per thread: parallel jobs never share one, and the worker's
  // PR_SET_PDEATHSIG fires when the thread that forked it ends, which is also when
  // this thread_local retires it.
  thread_local std::unique_ptr<RenderWorker> worker;
  WorkerSettings settings = SettingsFor(options);
  if (worker == nullptr || !(worker->Settings() == settings)) {
    worker.reset();  // retire the old one first: at most one worker per thread
    worker = std::make_unique<RenderWorker>(std::move(settings));
  }
  return worker->Render(request, options.timeout);
}

RenderOutcome RenderInFreshProcess(const RenderRequest& request, const RenderOptions& options) {
  WorkerSettings settings = SettingsFor(options);
  settings.max_renders = 1;
  RenderWorker worker(std::move(settings));
  return worker.Render(request, options.timeout);
}

unsigned ParallelRenderJobs(unsigned requested) {
#ifdef SHADERPORT_ASAN
  (void)requested;
  return 1;
#else
  return requested;
#endif
}

}  // namespace shaderport::render
