// Runs work on a thread with a large stack: glslang and SPIRV-Cross recurse over expression
// trees, and a deeply nested shader must not overflow the caller's stack.
#pragma once

#include <cstddef>
#include <functional>

namespace shaderport::toolchain {

inline constexpr size_t kEmitStackBytes = size_t{256} << 20;  // reserved, touched lazily

// Blocks until `work` has run; false (and `work` not run) if no thread could be started.
bool RunWithLargeStack(const std::function<void()>& work, size_t stack_bytes = kEmitStackBytes);

}  // namespace shaderport::toolchain
