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

}  // namespace shaderport
