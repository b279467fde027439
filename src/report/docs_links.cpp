#include "report/docs_links.h"

namespace shaderport {
namespace {

constexpr std::string_view kRulesPage = "/blob/main/docs/rules.md";
// The heading of the table that lists every id (driver/port/rule_reference.cpp).
constexpr std::string_view kEveryIdHeading = "Every diagnostic id";

}  // namespace

std::string GithubHeadingAnchor(std::string_view heading) {
  std::string anchor;
  for (char c : heading) {
    const auto byte = static_cast<unsigned char>(c);
    if (c >= 'A' && c <= 'Z') {
      anchor += static_cast<char>(c - 'A' + 'a');
    } else if (c == ' ') {
      anchor += '-';
    } else if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
               byte >= 0x80) {
      anchor += c;  // bytes of non-ASCII letters are kept, as GitHub keeps the letters
    }
  }
  return anchor;
}

std::string RuleHelpUri(std::string_view id, bool has_rule_section) {
  return std::string(kRepositoryUri) + std::string(kRulesPage) + "#" +
         GithubHeadingAnchor(has_rule_section ? id : kEveryIdHeading);
}

}  // namespace shaderport
