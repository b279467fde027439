// Every rule id shaderport can report, with a one-line description and help
// text. SARIF output, `shaderport explain` and docs/ are generated from it, and a
// test fails when the sources use an id that is not listed here.
#pragma once

#include <span>
#include <string_view>

namespace shaderport {

struct RuleDescription {
  std::string_view id;       // "category/kebab-name"
  std::string_view summary;  // one line, sentence case, no final period
  std::string_view help;     // what it means and what to do about it
};

// All entries, sorted by id.
std::span<const RuleDescription> RuleCatalog();

// nullptr when `id` is not in the catalog.
const RuleDescription* FindRule(std::string_view id);

}  // namespace shaderport
