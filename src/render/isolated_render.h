// Every render runs in a separate process forked before any GL context exists,
// with a wall-clock timeout and an address-space limit; the result comes back
// through a socket. A shader that hangs llvmpipe (there is no way to abort
// glDrawArrays) is killed, and the parent never holds GL state or driver threads.
// The process is a persistent worker (render_worker.h), one per calling thread.
#pragma once

#include "render/render_request.h"

namespace shaderport::render {

// Never throws and never leaves a process behind. Status kTimeout / kCrashed when
// the worker was killed or died (the next call gets a new one); kOk with pixels
// otherwise. SHADERPORT_RENDER_WORKER_RENDERS=N retires a worker after N renders
// (default 200; 1: a fresh process per render).
RenderOutcome RenderIsolated(const RenderRequest& request, const RenderOptions& options);

// The same render in a process of its own that serves only this request.
RenderOutcome RenderInFreshProcess(const RenderRequest& request, const RenderOptions& options);

// $XDG_CACHE_HOME/shaderport/mesa, or ~/.cache/shaderport/mesa.
std::string DefaultMesaCacheDir();

// How many threads may render at once for `requested` jobs (0: one per core). Each
// thread forks its own worker while other threads run: glibc's fork resets malloc's
// locks in the child, AddressSanitizer's allocator does not (a worker forked while
// another thread allocates could hang), so sanitized builds draw on one thread.
unsigned ParallelRenderJobs(unsigned requested);

}  // namespace shaderport::render
