#include "driver/largest_first.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <numeric>
#include <system_error>

#include "driver/read_input.h"

namespace shaderport::driver {
namespace {

uintmax_t SizeOf(const FileJob& job) {
  if (job.source != nullptr) return job.source->Text().size();
  if (job.contents != nullptr) return job.contents->text ? job.contents->text->size() : 0;
  std::error_code error;
  const uintmax_t size = std::filesystem::file_size(job.path, error);
  return error ? 0 : size;
}

}  // namespace

std::vector<size_t> LargestFirst(const std::vector<FileJob>& jobs) {
  std::vector<uintmax_t> sizes(jobs.size());
  for (size_t i = 0; i < jobs.size(); ++i) sizes[i] = SizeOf(jobs[i]);
  std::vector<size_t> order(jobs.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return sizes[a] > sizes[b]; });
  return order;
}

}  // namespace shaderport::driver
