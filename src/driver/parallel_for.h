// Runs a job per index on a few threads. Each job writes only its own slot of
// the caller's result vector, so output order never depends on scheduling.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

#include "base/large_stack.h"

namespace shaderport::driver {

// Each job thread runs its whole share on a large-stack thread
// (base/large_stack.h), so glslang runs in place there: handing every file to a
// separate glslang thread and back cost two thread switches per file, and the two
// threads' caches on different cores.
template <typename Job>
void ParallelFor(size_t count, unsigned jobs, Job&& job) {
  if (jobs == 0) jobs = std::max(1u, std::thread::hardware_concurrency());
  jobs = static_cast<unsigned>(std::min<size_t>(jobs, std::max<size_t>(count, 1)));
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i = next++; i < count; i = next++) job(i);
  };
  auto on_large_stack = [&] {
    if (!RunOnLongLivedLargeStack(worker)) worker();  // no thread: as before, in place
  };
  if (jobs <= 1) {
    on_large_stack();
    return;
  }
  std::vector<std::jthread> threads;
  threads.reserve(jobs - 1);
  for (unsigned t = 1; t < jobs; ++t) threads.emplace_back(on_large_stack);
  on_large_stack();
}

}  // namespace shaderport::driver
