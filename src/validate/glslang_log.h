// Parses glslang's info log text into structured messages.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"

namespace shaderport::validate {

// One finding from glslang's log. `part` is the source-string name glslang printed
// ("" for messages without a location, such as link errors); `line` is 1-based
// within that part, 0 when absent.
struct GlslangMessage {
  Severity severity = Severity::kError;
  std::string part;
  uint32_t line = 0;
  std::string token;  // the quoted token, '' -> ""
  std::string text;   // glslang's text after the token, untouched except trimmed
};

// Tolerant of double and trailing spaces. Skips the summary lines that are not
// findings ("compilation terminated", "N compilation errors.  No code generated.")
// and joins indented continuation lines (link errors) onto the message before.
std::vector<GlslangMessage> ParseGlslangLog(std::string_view log);

}  // namespace shaderport::validate
