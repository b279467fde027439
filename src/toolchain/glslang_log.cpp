#include "toolchain/glslang_log.h"

#include <charconv>
#include <string>

#include "base/limits.h"

namespace shaderport::toolchain {
namespace {

// glslang's own summary and follow-up lines, which repeat what the real errors say.
bool IsSummary(std::string_view text) {
  return text.find("compilation errors.") != std::string_view::npos ||
         text.find("compilation terminated") != std::string_view::npos;
}

std::string_view Trim(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\r')) text.remove_suffix(1);
  return text;
}

// "0:12: 'x' : text" -> line 12 and "'x' : text"; line 0 when there is no location.
uint32_t SplitLocation(std::string_view& rest) {
  const size_t colon = rest.find(':');
  if (colon == std::string_view::npos) return 0;
  const size_t second = rest.find(':', colon + 1);
  if (second == std::string_view::npos) return 0;
  uint32_t line = 0;
  const std::string_view number = rest.substr(colon + 1, second - colon - 1);
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), line);
  if (error != std::errc() || end != number.data() + number.size()) return 0;
  rest = Trim(rest.substr(second + 1));
  return line;
}

}  // namespace

void AppendGlslangErrors(std::string_view log, const SourceFile& file, std::string_view rule_id,
                         Severity severity, std::string_view prefix, DiagnosticList& out) {
  constexpr std::string_view kError = "ERROR: ";
  bool reported = false;
  size_t count = 0;
  while (!log.empty()) {
    const size_t newline = log.find('\n');
    std::string_view line = log.substr(0, newline);
    log = newline == std::string_view::npos ? std::string_view() : log.substr(newline + 1);
    if (line.substr(0, kError.size()) != kError) continue;
    std::string_view rest = Trim(line.substr(kError.size()));
    if (IsSummary(rest)) continue;
    const uint32_t line_number = SplitLocation(rest);
    if (rest.substr(0, 4) == "'' :") rest = Trim(rest.substr(4));  // glslang names no token
    if (++count > limits::kMaxDiagnosticsPerFile) break;
    Diagnostic diagnostic;
    diagnostic.severity = severity;
    diagnostic.rule_id = std::string(rule_id);
    if (line_number >= 1 && line_number <= file.LineCount()) {
      const uint32_t begin = file.LineStart(line_number);
      diagnostic.range = {file.Id(), begin,
                          begin + static_cast<uint32_t>(file.LineText(line_number).size())};
    } else {
      diagnostic.range = {file.Id(), 0, 0};
    }
    diagnostic.message = std::string(prefix) + std::string(rest);
    out.push_back(std::move(diagnostic));
    reported = true;
  }
  if (!reported) {
    out.push_back({severity,
                   std::string(rule_id),
                   {file.Id(), 0, 0},
                   std::string(prefix) + "glslang failed without a message",
                   {},
                   {}});
  }
}

}  // namespace shaderport::toolchain
