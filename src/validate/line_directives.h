// glslang numbers lines as `#line` says; shaderport maps its messages by physical line.
#pragma once

#include <string>
#include <string_view>

namespace shaderport::validate {

// `text` with every `#line` directive turned into spaces (line ends kept, so offsets and
// physical lines stay), or an empty string when it has none. Our own preprocessor
// reports a bad `#line` (preprocessor/invalid-line, preprocessor/line-too-large);
// glslang, given `#line 4294967295`, numbered the next line -1 and every finding of the
// file landed on 1:1.
std::string WithoutLineDirectives(std::string_view text);

}  // namespace shaderport::validate
