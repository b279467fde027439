#include "progress_line.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace shaderport::cli {
namespace {

using namespace std::chrono_literals;

// A run shorter than this never shows a line in auto mode.
constexpr auto kShowAfter = 1s;
// Redrawing more often only costs terminal time.
constexpr auto kRedrawEvery = 100ms;

std::string Duration(double seconds) {
  const auto total = static_cast<long long>(seconds + 0.5);
  char text[32];
  if (total < 60) {
    std::snprintf(text, sizeof text, "%llds", total);
  } else if (total < 3600) {
    std::snprintf(text, sizeof text, "%lldm%02llds", total / 60, total % 60);
  } else {
    std::snprintf(text, sizeof text, "%lldh%02lldm", total / 3600, total % 3600 / 60);
  }
  return text;
}

// Columns of the terminal on standard error; 0 when unknown.
size_t TerminalWidth() {
  winsize size{};
  if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &size) != 0) return 0;
  return size.ws_col;
}

bool IsDumbTerminal() {
  const char* term = std::getenv("TERM");
  return term != nullptr && std::string_view(term) == "dumb";
}

}  // namespace

std::optional<ProgressMode> ParseProgressMode(std::string_view name) {
  if (name == "auto") return ProgressMode::kAuto;
  if (name == "always") return ProgressMode::kAlways;
  if (name == "never") return ProgressMode::kNever;
  return std::nullopt;
}

std::string ProgressText(std::string_view verb, size_t done, size_t total, double seconds) {
  std::string text = std::string(verb) + " " + std::to_string(done) + "/" + std::to_string(total) +
                     (total == 1 ? " file" : " files");
  if (done == 0 || seconds <= 0) return text;
  const double rate = static_cast<double>(done) / seconds;
  char rate_text[32];
  std::snprintf(rate_text, sizeof rate_text, "%.1f", rate);
  text += std::string(", ") + rate_text + " files/s, ETA " +
          Duration(static_cast<double>(total - done) / rate);
  return text;
}

ProgressLine::ProgressLine(ProgressMode mode, std::string verb)
    : forced_(mode == ProgressMode::kAlways), verb_(std::move(verb)) {
  enabled_ =
      forced_ || (mode == ProgressMode::kAuto && ::isatty(STDERR_FILENO) != 0 && !IsDumbTerminal());
}

ProgressLine::~ProgressLine() { Clear(); }

void ProgressLine::Update(size_t done, size_t total) {
  if (!enabled_) return;
  const std::lock_guard lock(mutex_);
  const Clock::time_point now = Clock::now();
  if (!forced_ && now - start_ < kShowAfter) return;
  // The last file is drawn when forced, so a short run still shows where it ended.
  const bool last = forced_ && done == total;
  if (last_draw_ && now - *last_draw_ < kRedrawEvery && !last) return;
  last_draw_ = now;
  std::string text =
      ProgressText(verb_, done, total, std::chrono::duration<double>(now - start_).count());
  // A line longer than the terminal would wrap, and "\r" could not take it back.
  const size_t width = TerminalWidth();
  if (width > 1 && text.size() >= width) text.resize(width - 1);
  std::fprintf(stderr, "\r%s\x1b[K", text.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressLine::Clear() {
  const std::lock_guard lock(mutex_);
  if (!drawn_) return;
  std::fputs("\r\x1b[K", stderr);
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace shaderport::cli
