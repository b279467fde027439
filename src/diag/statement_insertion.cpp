#include "diag/statement_insertion.h"

#include <string>

namespace shaderport {
namespace {

bool IsBlank(char c) { return c == ' ' || c == '\t'; }

std::string_view Indentation(std::string_view line) {
  size_t n = 0;
  while (n < line.size() && IsBlank(line[n])) ++n;
  return line.substr(0, n);
}

bool OnlyBlanks(std::string_view text) {
  for (char c : text) {
    if (!IsBlank(c) && c != '\r') return false;
  }
  return true;
}

// One level deeper than `outer`: the file's own unit (a tab when the brace's line is
// indented with tabs), else four spaces.
std::string Deeper(std::string_view outer) {
  if (!outer.empty() && outer.front() == '\t') return std::string(outer) + '\t';
  return std::string(outer) + "    ";
}

// The indentation of the first non-blank line from `first` on when it is deeper than
// `outer` (a statement of the block), else one level deeper than `outer`.
std::string BodyIndentation(const SourceFile& file, uint32_t first, std::string_view outer) {
  for (uint32_t line = first; line <= file.LineCount(); ++line) {
    const std::string_view text = file.LineText(line);
    if (OnlyBlanks(text)) continue;
    const std::string_view indent = Indentation(text);
    if (indent.size() > outer.size()) return std::string(indent);
    break;
  }
  return Deeper(outer);
}

// The terminator of `line`, which must not be the last line: "\r\n" or "\n".
std::string_view LineEnding(const SourceFile& file, uint32_t line) {
  const uint32_t next = file.LineStart(line + 1);
  return next >= 2 && file.Text()[next - 2] == '\r' ? "\r\n" : "\n";
}

}  // namespace

FixIt InsertFirstStatement(const SourceFile& file, uint32_t brace_end, std::string_view statement) {
  const LineColumn at = file.LocationOf(brace_end);
  const std::string_view line = file.LineText(at.line);
  const uint32_t line_start = file.LineStart(at.line);
  const std::string_view rest = line.substr(std::min<size_t>(brace_end - line_start, line.size()));
  if (!OnlyBlanks(rest) || at.line >= file.LineCount()) {
    return {{file.Id(), brace_end, brace_end}, " " + std::string(statement)};
  }
  const std::string indent = BodyIndentation(file, at.line + 1, Indentation(line));
  // After the brace's line: the brace's line keeps its own ending.
  const uint32_t next = file.LineStart(at.line + 1);
  return {{file.Id(), next, next},
          indent + std::string(statement) + std::string(LineEnding(file, at.line))};
}

FixIt InsertLastStatement(const SourceFile& file, uint32_t brace_begin,
                          std::string_view statement) {
  const LineColumn at = file.LocationOf(brace_begin);
  const std::string_view line = file.LineText(at.line);
  const uint32_t line_start = file.LineStart(at.line);
  const std::string_view before = line.substr(0, brace_begin - line_start);
  if (!OnlyBlanks(before) || at.line <= 1) {
    const bool spaced = brace_begin > 0 && IsBlank(file.Text()[brace_begin - 1]);
    return {{file.Id(), brace_begin, brace_begin},
            (spaced ? "" : " ") + std::string(statement) + " "};
  }
  // The statements above the brace, nearest first, set the indentation.
  std::string indent = Deeper(before);
  for (uint32_t above = at.line - 1; above >= 1; --above) {
    const std::string_view text = file.LineText(above);
    if (OnlyBlanks(text)) continue;
    const std::string_view candidate = Indentation(text);
    if (candidate.size() > before.size()) indent = std::string(candidate);
    break;
  }
  return {{file.Id(), line_start, line_start},
          indent + std::string(statement) + std::string(LineEnding(file, at.line - 1))};
}

}  // namespace shaderport
