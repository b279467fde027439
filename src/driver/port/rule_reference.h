// The rule reference: `shaderport rules` (and docs/rules.md, its output) and
// `shaderport explain ID`.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shaderport::driver {

// Every porting rule: id, scope, summary, help from the catalog, Before/After.
std::string RulesMarkdown();

// One line per porting rule, sorted by id, for terminals (`rules --list`): the id,
// the scope (which commands report or apply it) and the one-line summary.
std::string RulesList();

// The ids of the porting rules, sorted: each has its own section in docs/rules.md.
std::vector<std::string> PortingRuleIds();

// One porting rule, or any catalog entry (glslang/..., syntax/...); nullopt when unknown.
std::optional<std::string> ExplainRule(std::string_view id);

}  // namespace shaderport::driver
