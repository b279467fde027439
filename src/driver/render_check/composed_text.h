// A shader text assembled from generated and user parts, remembering which line
// of the result came from which file, so that Mesa's `0:LINE(COL)` maps back.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "source/source_file.h"

namespace shaderport::driver {

class ComposedText {
 public:
  // `file` null for generated text. A part is always followed by a newline.
  void Append(std::string_view text, const SourceFile* file);
  const std::string& Text() const { return text_; }
  // The user range of a 1-based line of Text(); nullopt for a generated line.
  std::optional<SourceRange> MapLine(uint32_t line) const;

 private:
  struct Part {
    uint32_t first_line = 1;  // in text_
    uint32_t line_count = 0;
    const SourceFile* file = nullptr;
  };
  std::string text_;
  uint32_t next_line_ = 1;
  std::vector<Part> parts_;
};

}  // namespace shaderport::driver
