// The worker's side (render_worker.h): sandbox the freshly forked process, then
// serve length-prefixed requests from `socket` until the parent closes it.
#pragma once

#include <sys/types.h>

#include "render/render_worker.h"

namespace shaderport::render {

// Exit statuses the parent turns into messages.
inline constexpr int kWorkerOutOfMemoryExit = 6;  // std::bad_alloc: the address-space limit
inline constexpr int kWorkerBadRequestExit = 7;

// Runs in the child right after fork, which may happen on a job thread while other
// threads run glslang (each on its own large-stack thread) or ports. The child never
// runs their code, and the C library locks it does take are reset by glibc's fork
// (malloc arenas, stdio streams, the dynamic loader's and thread-stack locks, NSS).
// Of those it is not, no thread of shaderport takes setenv's; atexit's is held for a
// few instructions when a thread first builds a static with a destructor (Mesa in
// the worker registers atexit handlers: at worst that render times out). Before the
// first render it only makes system calls and setenv, then creates its own
// contexts (Mesa and LLVM state exists only in workers).
[[noreturn]] void RunWorkerChild(int socket, pid_t parent, const WorkerSettings& settings);

}  // namespace shaderport::render
