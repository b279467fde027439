// Pieces of TextForGlslang (glslang_divergence.h) shared by its two files:
// glslang_text_names.cpp (renames) and glslang_text.cpp (directives, macros, the order).
#pragma once

#include <set>
#include <string>
#include <string_view>

#include "rules/webgl/glslang_divergence.h"

namespace shaderport::rules::glslang_text {

// The text of `file` as written: one of the unit's parts, or the user's file; else empty.
std::string_view OriginalText(const BrowserContext& context, FileId file);
// Every part's text (aliases must be new to all of them); `text` without parts.
std::string UnitText(const BrowserContext& context, std::string_view text);
// A name of `name`'s length that neither `text` nor `taken` contains, or "".
std::string SameLengthAlias(const std::string& text, const std::string& name,
                            const std::set<std::string>& taken = {});
// Replaces every whole word `word` of `text` by `with` (of the same length).
void ReplaceWord(std::string& text, std::string_view word, std::string_view with);

void RenameDeclarableBuiltins(const BrowserContext& context, FileId part, std::string& text);
void RenameGlslangOnlyKeywords(const BrowserContext& context, FileId part, std::string& text);
void RenameLengthFields(const BrowserContext& context, FileId part, std::string& text);

}  // namespace shaderport::rules::glslang_text
