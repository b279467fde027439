// The worker's side (render_worker.h): sandbox the freshly forked process, then
// serve length-prefixed requests from `socket` until the parent closes it.
#pragma once

#include <sys/types.h>

#include "render/render_worker.h"

namespace shaderport::render {

// Exit statuses the parent turns into messages.
inline constexpr int kWorkerOutOfMemoryExit = 6;  // std::bad_alloc: the address-space limit
inline constexpr int kWorkerBadRequestExit = 7;

// Runs in the child right after fork, which may have happened while other threads of
// the parent held locks: before the first render it only makes system calls and
// setenv (as the one-process-per-render model did), then creates its own contexts.
[[noreturn]] void RunWorkerChild(int socket, pid_t parent, const WorkerSettings& settings);

}  // namespace shaderport::render
