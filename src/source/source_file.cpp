#include "source/source_file.h"

#include <algorithm>

namespace shaderport {

SourceFile::SourceFile(FileId id, std::string name, std::string text, bool synthetic)
    : id_(id), name_(std::move(name)), text_(std::move(text)), synthetic_(synthetic) {
  line_starts_.push_back(0);
  const std::string_view all = text_;
  if (all.find('\r') == std::string_view::npos) {
    // No CR (nearly every file): jump from LF to LF instead of testing every byte.
    for (size_t at = all.find('\n'); at != std::string_view::npos; at = all.find('\n', at + 1)) {
      line_starts_.push_back(static_cast<uint32_t>(at + 1));
    }
    return;
  }
  for (uint32_t i = 0; i < text_.size(); ++i) {
    // "\r\n", "\n" and a lone "\r" each end a line, as in GLSL ES 3.00 section 3.1.
    if (text_[i] == '\r') {
      if (i + 1 < text_.size() && text_[i + 1] == '\n') ++i;
      line_starts_.push_back(i + 1);
    } else if (text_[i] == '\n') {
      line_starts_.push_back(i + 1);
    }
  }
}

LineColumn SourceFile::LocationOf(uint32_t offset) const {
  offset = std::min<uint32_t>(offset, static_cast<uint32_t>(text_.size()));
  auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const auto line_index = static_cast<uint32_t>(it - line_starts_.begin()) - 1;
  return {line_index + 1, offset - line_starts_[line_index] + 1};
}

uint32_t SourceFile::LineStart(uint32_t line) const {
  if (line == 0) return 0;
  if (line > line_starts_.size()) return static_cast<uint32_t>(text_.size());
  return line_starts_[line - 1];
}

std::string_view SourceFile::LineText(uint32_t line) const {
  if (line == 0 || line > line_starts_.size()) return {};
  const uint32_t begin = line_starts_[line - 1];
  uint32_t end =
      line < line_starts_.size() ? line_starts_[line] : static_cast<uint32_t>(text_.size());
  while (end > begin && (text_[end - 1] == '\n' || text_[end - 1] == '\r')) --end;
  return std::string_view(text_).substr(begin, end - begin);
}

uint32_t SourceFile::OffsetOf(LineColumn location) const {
  const uint32_t begin = LineStart(location.line);
  const auto line_length = static_cast<uint32_t>(LineText(location.line).size());
  return begin + std::min(location.column > 0 ? location.column - 1 : 0, line_length);
}

}  // namespace shaderport
