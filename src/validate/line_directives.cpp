#include "validate/line_directives.h"

namespace shaderport::validate {
namespace {

bool IsBlank(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v'; }

// The end of the directive starting at `begin`: its line end, past continued lines.
size_t DirectiveEnd(std::string_view text, size_t begin) {
  size_t i = begin;
  while (i < text.size() && text[i] != '\n' && text[i] != '\r') {
    if (text[i] == '\\' && i + 1 < text.size() && (text[i + 1] == '\n' || text[i + 1] == '\r')) {
      i += (text[i + 1] == '\r' && i + 2 < text.size() && text[i + 2] == '\n') ? 3 : 2;
      continue;
    }
    ++i;
  }
  return i;
}

// `#line N` or `#line N M` with decimal numbers (a trailing // comment allowed): only
// such a directive is blanked. Any other one (a name, a macro, an expression) stays for
// glslang to judge, as browsers reject some ("'x' : invalid file number").
bool PlainLineArguments(std::string_view arguments) {
  size_t i = 0;
  int numbers = 0;
  while (true) {
    while (i < arguments.size() && IsBlank(arguments[i])) ++i;
    if (i == arguments.size() || arguments.substr(i, 2) == "//") return numbers >= 1;
    if (arguments[i] < '0' || arguments[i] > '9' || numbers == 2) return false;
    while (i < arguments.size() && arguments[i] >= '0' && arguments[i] <= '9') ++i;
    ++numbers;
    if (i < arguments.size() && !IsBlank(arguments[i]) && arguments.substr(i, 2) != "//")
      return false;
  }
}

}  // namespace

std::string WithoutLineDirectives(std::string_view text) {
  if (text.find("line") == std::string_view::npos) return {};
  std::string out;
  size_t line_start = 0;
  while (line_start < text.size()) {
    size_t i = line_start;
    while (i < text.size() && IsBlank(text[i])) ++i;
    size_t end = i;
    if (i < text.size() && text[i] == '#') {
      size_t name = i + 1;
      while (name < text.size() && IsBlank(text[name])) ++name;
      const bool is_line =
          text.substr(name, 4) == "line" && (name + 4 == text.size() || IsBlank(text[name + 4]) ||
                                             text[name + 4] == '\n' || text[name + 4] == '\r');
      end = DirectiveEnd(text, i);
      if (is_line && PlainLineArguments(text.substr(name + 4, end - name - 4))) {
        if (out.empty()) out = std::string(text);
        for (size_t k = i; k < end; ++k) {
          if (out[k] != '\n' && out[k] != '\r') out[k] = ' ';
        }
      }
    }
    const size_t newline = text.find_first_of("\r\n", end);
    if (newline == std::string_view::npos) break;
    line_start = newline + 1;
  }
  return out;
}

}  // namespace shaderport::validate
