// The progress line of long runs on a terminal:
//   checking 120/900 files, 41.5 files/s, ETA 19s
// redrawn in place on standard error and erased before the results are printed,
// so it never mixes with what goes to standard output.
#pragma once

#include <chrono>
#include <cstddef>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>

namespace shaderport::cli {

// --progress: auto shows the line only when standard error is a terminal and the
// run has lasted a second; always draws it from the first file (for tests and
// logs); never is never.
enum class ProgressMode { kAuto, kAlways, kNever };

std::optional<ProgressMode> ParseProgressMode(std::string_view name);

// "checking 3/10 files, 2.5 files/s, ETA 3s"
std::string ProgressText(std::string_view verb, size_t done, size_t total, double seconds);

class ProgressLine {
 public:
  ProgressLine(ProgressMode mode, std::string verb);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // Safe to call from several threads.
  void Update(size_t done, size_t total);
  // Erases the line (if one was drawn); call before printing results.
  void Clear();

 private:
  using Clock = std::chrono::steady_clock;

  bool enabled_ = false;
  bool forced_ = false;
  std::string verb_;
  Clock::time_point start_ = Clock::now();
  std::optional<Clock::time_point> last_draw_;
  bool drawn_ = false;
  std::mutex mutex_;
};

}  // namespace shaderport::cli
