// Runs a job per index on a few threads. Each job writes only its own slot of
// the caller's result vector, so output order never depends on scheduling.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <span>
#include <thread>
#include <vector>

#include "base/large_stack.h"

namespace shaderport::driver {

// Each job thread runs its whole share on a large-stack thread
// (base/large_stack.h), so glslang runs in place there: handing every file to a
// separate glslang thread and back cost two thread switches per file, and the two
// threads' caches on different cores.
//
// The jobs take the indices in `order` when it is given (a permutation of 0..count-1),
// else in increasing order: handing the largest pieces of work out first keeps one long
// job late in the list from finishing alone while the other threads sit idle.
template <typename Job>
void ParallelFor(size_t count, unsigned jobs, Job&& job, std::span<const size_t> order = {}) {
  if (jobs == 0) jobs = std::max(1u, std::thread::hardware_concurrency());
  jobs = static_cast<unsigned>(std::min<size_t>(jobs, std::max<size_t>(count, 1)));
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t k = next++; k < count; k = next++) job(order.empty() ? k : order[k]);
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
