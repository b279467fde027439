// Rule patterns shared by .shaderport.toml [rules] and suppression comments:
// "category/name" (one rule), "category/*" (a category) or "*" (every rule).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace shaderport::driver {

// True when `pattern` has one of the three forms, with ids of [a-z0-9-] words.
bool IsValidRulePattern(std::string_view pattern);

bool RulePatternMatches(std::string_view pattern, std::string_view rule_id);

// Higher is more specific: an exact id beats "category/*", which beats "*".
int RulePatternSpecificity(std::string_view pattern);

// True when some rule of the catalog matches `pattern`.
bool RulePatternMatchesCatalog(std::string_view pattern);

// For a pattern that matches nothing: the nearest catalog id (or "category/*"
// for a category pattern) when it is a likely typo of one.
std::optional<std::string> NearestCatalogPattern(std::string_view pattern);

}  // namespace shaderport::driver
