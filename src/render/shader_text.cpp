#include "render/shader_text.h"

#include <cctype>

namespace shaderport::render {
namespace {

bool IsIdent(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

size_t CountWord(const std::string& text, const std::string& word) {
  size_t count = 0;
  for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const bool left = at == 0 || !IsIdent(text[at - 1]);
    const bool right = at + word.size() >= text.size() || !IsIdent(text[at + word.size()]);
    if (left && right) ++count;
  }
  return count;
}

}  // namespace

std::string BlankComments(std::string_view text) {
  std::string out(text);
  for (size_t i = 0; i + 1 < out.size(); ++i) {
    if (out[i] == '/' && out[i + 1] == '/') {
      while (i < out.size() && out[i] != '\n') out[i++] = ' ';
    } else if (out[i] == '/' && out[i + 1] == '*') {
      const size_t end = out.find("*/", i + 2);
      const size_t stop = end == std::string::npos ? out.size() : end + 2;
      for (; i < stop; ++i) {
        if (out[i] != '\n') out[i] = ' ';
      }
    }
  }
  return out;
}

std::vector<std::string> UnusedOutputs(std::string_view fragment_text) {
  const std::string text = BlankComments(fragment_text);
  std::vector<std::string> unused;
  size_t line_start = 0;
  while (line_start < text.size()) {
    size_t line_end = text.find('\n', line_start);
    if (line_end == std::string::npos) line_end = text.size();
    std::string_view line(text.data() + line_start, line_end - line_start);
    line_start = line_end + 1;
    if (line.starts_with("layout")) {
      const size_t close = line.find(')');
      if (close == std::string_view::npos) continue;
      line.remove_prefix(close + 1);
    }
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.front()))) {
      line.remove_prefix(1);
    }
    if (!line.starts_with("out ")) continue;
    // out [precision] type name;  -> the identifier before ';' or '['
    const size_t semicolon = line.find_first_of(";[");
    if (semicolon == std::string_view::npos) continue;
    size_t end = semicolon;
    while (end > 0 && std::isspace(static_cast<unsigned char>(line[end - 1]))) --end;
    size_t begin = end;
    while (begin > 0 && IsIdent(line[begin - 1])) --begin;
    const std::string name(line.substr(begin, end - begin));
    if (!name.empty() && CountWord(text, name) == 1) unused.push_back(name);
  }
  return unused;
}

}  // namespace shaderport::render
