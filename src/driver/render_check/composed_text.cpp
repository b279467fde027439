#include "driver/render_check/composed_text.h"

#include <algorithm>

namespace shaderport::driver {

void ComposedText::Append(std::string_view text, const SourceFile* file) {
  Part part;
  part.first_line = next_line_;
  part.file = file;
  text_ += text;
  if (text.empty() || text.back() != '\n') text_ += '\n';
  part.line_count = static_cast<uint32_t>(std::count(text.begin(), text.end(), '\n'));
  if (text.empty() || text.back() != '\n') ++part.line_count;
  next_line_ += part.line_count;
  parts_.push_back(part);
}

std::optional<SourceRange> ComposedText::MapLine(uint32_t line) const {
  for (const Part& part : parts_) {
    if (line < part.first_line || line >= part.first_line + part.line_count) continue;
    if (part.file == nullptr) return std::nullopt;
    const uint32_t user_line = line - part.first_line + 1;
    const uint32_t begin = part.file->LineStart(user_line);
    const auto end = static_cast<uint32_t>(begin + part.file->LineText(user_line).size());
    return SourceRange{part.file->Id(), begin, end};
  }
  return std::nullopt;
}

}  // namespace shaderport::driver
