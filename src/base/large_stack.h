// Runs a function on a thread with a large dedicated stack, so that deep
// recursion in a library (glslang or SPIRV-Cross on hostile input) cannot
// overflow the caller's.
#pragma once

#include <cstddef>
#include <functional>

namespace shaderport {

inline constexpr size_t kLargeStackBytes = size_t{256} << 20;  // reserved, touched lazily

// Blocks until `work` has run. Returns false if the thread could not be started
// (then `work` did not run).
bool RunOnLargeStack(const std::function<void()>& work, size_t stack_bytes = kLargeStackBytes);

// The same on a thread with a kLargeStackBytes stack that the calling thread keeps
// for its whole life (one per calling thread, joined when it exits), instead of a
// fresh one each call: creating and tearing down a 256 MiB-stack thread for every
// file cost system time (the stack's mapping and its page faults) for each glslang
// run. Work from one calling thread therefore runs on the same thread every time,
// with whatever thread-local state the library keeps. In a process forked from one
// that had such a thread, a new thread is started (the old one does not exist there).
// Called on a thread started here (already on a large stack), runs `work` in place.
bool RunOnLongLivedLargeStack(const std::function<void()>& work);

}  // namespace shaderport
