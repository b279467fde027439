#include "driver/suppress/suppression_comment.h"

#include "driver/config/rule_pattern.h"

namespace shaderport::driver {
namespace {

constexpr std::string_view kIgnore = "shaderport-ignore";
constexpr std::string_view kNextLine = "-next-line";

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v'; }

bool IsWordChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
         c == '_';
}

}  // namespace

std::optional<SuppressionDirective> ParseSuppressionComment(std::string_view comment) {
  size_t p = 0;
  if (comment.substr(0, 2) == "//" || comment.substr(0, 2) == "/*") p = 2;
  size_t end = comment.size();
  if (comment.substr(0, 2) == "/*" && end >= 4 && comment.substr(end - 2) == "*/") end -= 2;
  while (p < end && IsSpace(comment[p])) ++p;
  if (comment.substr(p, kIgnore.size()) != kIgnore) return std::nullopt;
  p += kIgnore.size();

  SuppressionDirective directive;
  if (comment.substr(p, kNextLine.size()) == kNextLine) {
    directive.next_line = true;
    p += kNextLine.size();
  }
  if (p < end && IsWordChar(comment[p])) {
    // "shaderport-ignored" or "shaderport-ignore-line": looks meant, but is not a directive.
    size_t word_end = p;
    while (word_end < end && IsWordChar(comment[word_end])) ++word_end;
    directive.error = "unknown suppression directive 'shaderport-ignore" +
                      std::string(comment.substr(p, word_end - p)) +
                      "'; use shaderport-ignore or shaderport-ignore-next-line";
    return directive;
  }
  if (p >= end || comment[p] != '(') return directive;  // no list: every rule

  const size_t close = comment.find(')', p);
  if (close == std::string_view::npos || close > end) {
    directive.error = "missing ')' after the rule list";
    return directive;
  }
  size_t item = p + 1;
  while (item <= close) {
    size_t comma = comment.find(',', item);
    if (comma == std::string_view::npos || comma > close) comma = close;
    size_t begin = item;
    size_t last = comma;
    while (begin < last && IsSpace(comment[begin])) ++begin;
    while (last > begin && IsSpace(comment[last - 1])) --last;
    const std::string_view pattern = comment.substr(begin, last - begin);
    if (pattern.empty()) {
      directive.error = comma == close && directive.patterns.empty()
                            ? "empty rule list; omit the parentheses to silence every rule"
                            : "empty rule id in the list";
      return directive;
    }
    if (!IsValidRulePattern(pattern)) {
      directive.error =
          "'" + std::string(pattern) + "' is not a rule id; write 'category/name' or 'category/*'";
      return directive;
    }
    directive.patterns.push_back({std::string(pattern), static_cast<uint32_t>(begin)});
    item = comma + 1;
  }
  return directive;
}

}  // namespace shaderport::driver
