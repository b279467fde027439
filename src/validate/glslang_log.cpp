#include "validate/glslang_log.h"

#include <cctype>
#include <optional>

namespace shaderport::validate {
namespace {

std::string_view Trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

bool ConsumePrefix(std::string_view& s, std::string_view prefix) {
  if (!s.starts_with(prefix)) return false;
  s.remove_prefix(prefix.size());
  return true;
}

// "ERROR:", "WARNING:" ... at the start of a line.
std::optional<Severity> ConsumeSeverity(std::string_view& line) {
  if (ConsumePrefix(line, "ERROR:") || ConsumePrefix(line, "INTERNAL ERROR:") ||
      ConsumePrefix(line, "UNIMPLEMENTED:")) {
    return Severity::kError;
  }
  if (ConsumePrefix(line, "WARNING:")) return Severity::kWarning;
  if (ConsumePrefix(line, "NOTE:")) return Severity::kNote;
  return std::nullopt;
}

// "<part>:<line>:" with a decimal line; the part name has no ':' (we choose it).
bool ConsumeLocation(std::string_view& rest, GlslangMessage& message) {
  const size_t colon = rest.find(':');
  if (colon == std::string_view::npos || colon == 0) return false;
  size_t end = colon + 1;
  uint64_t line = 0;
  while (end < rest.size() && std::isdigit(static_cast<unsigned char>(rest[end]))) {
    line = std::min<uint64_t>(line * 10 + static_cast<uint64_t>(rest[end] - '0'), UINT32_MAX);
    ++end;
  }
  if (end == colon + 1 || end >= rest.size() || rest[end] != ':') return false;
  message.part = std::string(Trim(rest.substr(0, colon)));
  message.line = static_cast<uint32_t>(line);
  rest.remove_prefix(end + 1);
  return true;
}

// "'<token>' : <text>"; the token may itself contain quotes, so it ends at the
// first "'" followed by optional spaces and ':'.
void SplitTokenAndText(std::string_view rest, GlslangMessage& message) {
  rest = Trim(rest);
  if (rest.starts_with('\'')) {
    for (size_t i = 1; i < rest.size(); ++i) {
      if (rest[i] != '\'') continue;
      size_t j = i + 1;
      while (j < rest.size() && rest[j] == ' ') ++j;
      if (j < rest.size() && rest[j] == ':') {
        message.token = std::string(rest.substr(1, i - 1));
        message.text = std::string(Trim(rest.substr(j + 1)));
        return;
      }
    }
  }
  message.text = std::string(rest);
}

bool IsSummary(const GlslangMessage& message) {
  const std::string_view text = message.text;
  if (message.token.empty() && text == "compilation terminated") return true;
  // "2 compilation errors.  No code generated." and its singular form.
  return message.part.empty() && text.find("compilation error") != std::string_view::npos &&
         text.find("No code generated") != std::string_view::npos;
}

}  // namespace

std::vector<GlslangMessage> ParseGlslangLog(std::string_view log) {
  std::vector<GlslangMessage> messages;
  bool last_was_summary = true;  // continuation lines attach only to a real message
  while (!log.empty()) {
    size_t newline = log.find('\n');
    std::string_view raw = log.substr(0, newline);
    log.remove_prefix(newline == std::string_view::npos ? log.size() : newline + 1);
    if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
    if (Trim(raw).empty()) continue;

    std::string_view line = raw;
    const std::optional<Severity> severity = ConsumeSeverity(line);
    if (!severity) {
      // Indented continuation (e.g. the signature after "No function definition (body) found:").
      if (!last_was_summary && !messages.empty()) {
        std::string& text = messages.back().text;
        if (!text.empty()) text += ' ';
        text += Trim(raw);
      }
      continue;
    }
    GlslangMessage message;
    message.severity = *severity;
    std::string_view rest = Trim(line);
    if (ConsumeLocation(rest, message)) {
      SplitTokenAndText(rest, message);
    } else {
      message.text = std::string(rest);
    }
    last_was_summary = IsSummary(message);
    if (!last_was_summary) messages.push_back(std::move(message));
  }
  return messages;
}

}  // namespace shaderport::validate
