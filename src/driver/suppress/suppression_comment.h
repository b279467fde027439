// Reads one comment as a suppression directive:
//   // shaderport-ignore                       every rule, on this line
//   // shaderport-ignore(rule/id, cat/*)      those rules, on this line
//   // shaderport-ignore-next-line(rule/id)   those rules, on the next line
// The directive must open the comment; text after the closing ')' is a free-form reason.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shaderport::driver {

struct RulePatternSpan {
  std::string pattern;
  uint32_t offset = 0;  // byte offset of the pattern within the comment text
};

struct SuppressionDirective {
  bool next_line = false;
  std::vector<RulePatternSpan> patterns;  // empty: every rule
  std::string error;                      // non-empty: the directive is malformed
};

// nullopt when the comment is no suppression at all. `comment` is the comment
// with its "//" or "/* */" markers, exactly as in the file.
std::optional<SuppressionDirective> ParseSuppressionComment(std::string_view comment);

}  // namespace shaderport::driver
