// Small text scans of GLSL source for the render checks (the render layer sits
// below the GLSL front end, so these work on text, not on a syntax tree).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace shaderport::render {

// `text` with comments replaced by spaces (newlines kept, so offsets still match).
std::string BlankComments(std::string_view text);

// Names of global `out` variables (fragment outputs) that the text never mentions
// again after their declaration: such an output is never written.
std::vector<std::string> UnusedOutputs(std::string_view fragment_text);

}  // namespace shaderport::render
