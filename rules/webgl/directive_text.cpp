#include "rules/webgl/directive_text.h"

namespace shaderport::rules::directive_text {
namespace {

bool IsBlank(char c) { return c == ' ' || c == '\t'; }
bool IsDigit(char c) { return c >= '0' && c <= '9'; }
bool IsHexDigit(char c) { return IsDigit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }
bool IsIdentifierStart(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

size_t SkipBlanks(std::string_view text, size_t at) {
  while (at < text.size() && IsBlank(text[at])) ++at;
  return at;
}

// Just after the identifier at `at`, or `at` when there is none.
size_t IdentifierEnd(std::string_view text, size_t at) {
  if (at >= text.size() || !IsIdentifierStart(text[at])) return at;
  while (at < text.size() && IsWordChar(text[at])) ++at;
  return at;
}

// Just after the unsigned literal's digits at `at` (hex or decimal), or `at`.
size_t UnsignedDigitsEnd(std::string_view text, size_t at) {
  if (at + 2 < text.size() && text[at] == '0' && (text[at + 1] == 'x' || text[at + 1] == 'X') &&
      IsHexDigit(text[at + 2])) {
    size_t end = at + 2;
    while (end < text.size() && IsHexDigit(text[end])) ++end;
    if (end < text.size() && (text[end] == 'u' || text[end] == 'U')) return end;
  }
  size_t end = at;
  while (end < text.size() && IsDigit(text[end])) ++end;
  return end;
}

}  // namespace

bool IsWordChar(char c) { return IsIdentifierStart(c) || IsDigit(c); }

bool ContainsWord(std::string_view text, std::string_view word) {
  if (word.empty()) return false;
  for (size_t at = text.find(word); at != std::string_view::npos; at = text.find(word, at + 1)) {
    const bool starts = at == 0 || !IsWordChar(text[at - 1]);
    const size_t end = at + word.size();
    if (starts && (end == text.size() || !IsWordChar(text[end]))) return true;
  }
  return false;
}

std::string_view DirectiveKeyword(std::string_view line) {
  size_t at = SkipBlanks(line, 0);
  if (at >= line.size() || line[at] != '#') return {};
  at = SkipBlanks(line, at + 1);
  size_t end = at;
  while (end < line.size() && line[end] >= 'a' && line[end] <= 'z') ++end;
  return line.substr(at, end - at);
}

std::optional<DefineLine> ParseDefine(std::string_view line) {
  size_t at = SkipBlanks(line, 0);
  if (at >= line.size() || line[at] != '#') return std::nullopt;
  at = SkipBlanks(line, at + 1);
  if (line.substr(at, 6) != "define") return std::nullopt;
  at += 6;
  const size_t name_begin = SkipBlanks(line, at);
  if (name_begin == at) return std::nullopt;  // `#defineX`
  const size_t name_end = IdentifierEnd(line, name_begin);
  if (name_end == name_begin) return std::nullopt;
  return DefineLine{line.substr(name_begin, name_end - name_begin), name_begin, name_end,
                    name_end < line.size() && line[name_end] == '('};
}

bool IsDirective(std::string_view line, std::string_view keyword) {
  const std::string_view found = DirectiveKeyword(line);
  if (found != keyword) return false;
  const size_t end = static_cast<size_t>(found.data() - line.data()) + found.size();
  return end == line.size() || !IsWordChar(line[end]);
}

bool IsIfOrElif(std::string_view line) {
  return IsDirective(line, "if") || IsDirective(line, "elif");
}

std::optional<UnsignedDefine> ParseUnsignedDefine(std::string_view line) {
  const auto define = ParseDefine(line);
  if (!define || define->function_like) return std::nullopt;
  size_t at = SkipBlanks(line, define->name_end);
  if (at == define->name_end) return std::nullopt;  // NAME must be followed by a blank
  if (at < line.size() && line[at] == '(') at = SkipBlanks(line, at + 1);
  const size_t digits_end = UnsignedDigitsEnd(line, at);
  if (digits_end == at || digits_end >= line.size() ||
      (line[digits_end] != 'u' && line[digits_end] != 'U')) {
    return std::nullopt;
  }
  UnsignedDefine result{std::string(define->name), std::string(line.substr(at, digits_end - at))};
  at = SkipBlanks(line, digits_end + 1);
  if (at < line.size() && line[at] == ')') at = SkipBlanks(line, at + 1);
  if (at < line.size() && line[at] == '\r') ++at;
  if (at == line.size() || line.substr(at, 2) == "//") return result;
  return std::nullopt;
}

std::string WithoutUnsignedSuffixes(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    const bool starts = IsDigit(text[i]) && (i == 0 || !IsWordChar(text[i - 1]));
    if (starts) {
      const size_t end = UnsignedDigitsEnd(text, i);
      const bool suffix = end < text.size() && (text[end] == 'u' || text[end] == 'U') &&
                          (end + 1 == text.size() || !IsWordChar(text[end + 1]));
      if (suffix) {
        out.append(text.substr(i, end - i));
        i = end + 1;
        continue;
      }
    }
    out.push_back(text[i++]);
  }
  return out;
}

bool IsEmptyCall(std::string_view text) {
  const size_t name_end = IdentifierEnd(text, 0);
  if (name_end == 0) return false;
  size_t at = SkipBlanks(text, name_end);
  if (at >= text.size() || text[at] != '(') return false;
  at = SkipBlanks(text, at + 1);
  return at + 1 == text.size() && text[at] == ')';
}

bool HasEmptyArgument(std::string_view text) {
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '(' && text[i] != ',') continue;
    const size_t next = SkipBlanks(text, i + 1);
    if (next < text.size() && (text[next] == ',' || (text[i] == ',' && text[next] == ')'))) {
      return true;
    }
  }
  return false;
}

}  // namespace shaderport::rules::directive_text
