// Lines inside a skipped `#if` group are emptied, except the conditional directives
// that give the groups their shape: browsers (ANGLE's preprocessor, like glslang and
// a C preprocessor) ignore whatever else a skipped group holds, such as a misspelled
// `#elseif 1` under `#if 0`, but Mesa's preprocessor rejects it. Newlines stay, so
// line numbers do not move.
#include <algorithm>
#include <string_view>

#include "glsl/webgl_semantics/semantics_context.h"

namespace shaderport::glsl {
namespace {

bool IsConditionalDirective(std::string_view line) {
  const size_t hash = line.find_first_not_of(" \t");
  if (hash == std::string_view::npos || line[hash] != '#') return false;
  const size_t name = line.find_first_not_of(" \t", hash + 1);
  if (name == std::string_view::npos) return false;
  const std::string_view rest = line.substr(name);
  for (const std::string_view directive : {"ifdef", "ifndef", "if", "elif", "else", "endif"}) {
    if (rest.starts_with(directive) &&
        (rest.size() == directive.size() || rest[directive.size()] == ' ' ||
         rest[directive.size()] == '\t' || rest[directive.size()] == '(' ||
         rest[directive.size()] == '\r')) {
      return true;
    }
  }
  return false;
}

}  // namespace

void EmptyInactiveLines(std::span<const SourceFile* const> parts,
                        const PreprocessResult& preprocessed, EditCollector& edits) {
  for (const SourceRange& region : preprocessed.inactive_regions) {
    const SourceFile* file = nullptr;
    for (const SourceFile* part : parts) {
      if (part->Id() == region.file) file = part;
    }
    if (file == nullptr || region.end > file->Text().size()) continue;
    const std::string_view text = file->Text();
    const std::string_view inside = text.substr(region.begin, region.end - region.begin);
    if (inside.find('\\') != std::string_view::npos ||
        inside.find("/*") != std::string_view::npos) {
      continue;  // a continued line or a comment that may run out of the group
    }
    for (uint32_t at = region.begin; at < region.end;) {
      const size_t newline = text.find('\n', at);
      const auto end = static_cast<uint32_t>(
          std::min<size_t>(newline == std::string_view::npos ? text.size() : newline, region.end));
      const std::string_view line = text.substr(at, end - at);
      const bool has_content = line.find_first_not_of(" \t\r") != std::string_view::npos;
      if (has_content && !IsConditionalDirective(line)) {
        edits.Replace({region.file, at, end}, "");
      }
      at = end + 1;
    }
  }
}

}  // namespace shaderport::glsl
