#include "driver/project/json_code_rewrite.h"

#include <algorithm>

#include "driver/project/json_code_strings.h"

namespace shaderport::driver::project {
namespace {

// The escaped form of `text` without the surrounding quotes.
std::string Escaped(std::string_view text) {
  std::string literal = EncodeJsonString(text);
  return literal.substr(1, literal.size() - 2);
}

// False inside a multi-byte escape (\u00e9 decodes to two bytes with one offset).
bool OnEscapeBoundary(const std::vector<uint32_t>& offsets, uint32_t index) {
  return index == 0 || index >= offsets.size() || offsets[index] != offsets[index - 1];
}

std::string NewLiteral(std::string_view document, const CodeReplacement& replacement) {
  const CodeOrigin& origin = replacement.pass->origin;
  const std::vector<uint32_t>& offsets = origin.document_offsets;
  std::string literal = "\"";
  for (const MapSegment& segment : replacement.map->Segments()) {
    if (segment.inserted || segment.original_end >= offsets.size() ||
        !OnEscapeBoundary(offsets, segment.original_begin) ||
        !OnEscapeBoundary(offsets, segment.original_end)) {
      literal += Escaped(replacement.text.substr(segment.output_begin, segment.length));
      continue;
    }
    const uint32_t begin = offsets[segment.original_begin];
    const uint32_t end = offsets[segment.original_end];
    literal += document.substr(begin, end - begin);
  }
  literal += '"';
  return literal;
}

}  // namespace

std::string RewriteCodeStrings(std::string_view document,
                               std::vector<CodeReplacement> replacements) {
  std::sort(replacements.begin(), replacements.end(),
            [](const CodeReplacement& a, const CodeReplacement& b) {
              return a.pass->origin.literal_begin < b.pass->origin.literal_begin;
            });
  std::string out;
  out.reserve(document.size());
  size_t copied = 0;
  for (const CodeReplacement& replacement : replacements) {
    const CodeOrigin& origin = replacement.pass->origin;
    out += document.substr(copied, origin.literal_begin - copied);
    out += NewLiteral(document, replacement);
    copied = origin.literal_end;
  }
  out += document.substr(copied);
  return out;
}

}  // namespace shaderport::driver::project
