// Where shaderport's documentation lives online, for the links SARIF carries
// (tool.driver.informationUri and each rule's helpUri).
#pragma once

#include <string>
#include <string_view>

namespace shaderport {

// The project's home; the docs are its docs/ folder on the main branch.
inline constexpr std::string_view kRepositoryUri = "https://github.com/shaderport/shaderport";

// The anchor GitHub gives a Markdown heading: lower case, spaces become '-',
// punctuation other than '-' and '_' is dropped ("## port/version" -> "webgl2version").
std::string GithubHeadingAnchor(std::string_view heading);

// The docs page of rule `id`: its own section of docs/rules.md when it has one
// (the porting rules), else the table of every diagnostic id at the end of that page.
std::string RuleHelpUri(std::string_view id, bool has_rule_section);

}  // namespace shaderport
