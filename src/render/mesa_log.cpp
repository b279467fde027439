#include "render/mesa_log.h"

#include <charconv>

namespace shaderport::render {
namespace {

std::string_view Trim(std::string_view text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' '))
    text.remove_suffix(1);
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  return text;
}

// Parses "S:L(C): " at the start of `text`; returns the line or 0.
uint32_t ParseLocation(std::string_view& text) {
  uint32_t string_index = 0;
  uint32_t line = 0;
  uint32_t column = 0;
  const char* p = text.data();
  const char* end = text.data() + text.size();
  auto r = std::from_chars(p, end, string_index);
  if (r.ec != std::errc() || r.ptr == end || *r.ptr != ':') return 0;
  r = std::from_chars(r.ptr + 1, end, line);
  if (r.ec != std::errc() || r.ptr == end || *r.ptr != '(') return 0;
  r = std::from_chars(r.ptr + 1, end, column);
  if (r.ec != std::errc() || end - r.ptr < 2 || r.ptr[0] != ')' || r.ptr[1] != ':') return 0;
  text.remove_prefix(static_cast<size_t>(r.ptr + 2 - p));
  return line;
}

}  // namespace

std::vector<MesaLogEntry> ParseMesaLog(std::string_view log) {
  std::vector<MesaLogEntry> entries;
  while (!log.empty()) {
    const size_t newline = log.find('\n');
    std::string_view line = log.substr(0, newline);
    log = newline == std::string_view::npos ? std::string_view() : log.substr(newline + 1);
    line = Trim(line);
    if (line.empty()) continue;
    MesaLogEntry entry;
    entry.line = ParseLocation(line);
    line = Trim(line);
    if (line.starts_with("error:")) {
      line.remove_prefix(6);
    } else if (line.starts_with("warning:")) {
      entry.is_error = false;
      line.remove_prefix(8);
    } else if (entry.line == 0 && !entries.empty()) {
      // A continuation line (candidate lists): part of the previous message.
      entries.back().message += "; " + std::string(line);
      continue;
    }
    entry.message = std::string(Trim(line));
    entries.push_back(std::move(entry));
  }
  return entries;
}

}  // namespace shaderport::render
