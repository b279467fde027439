#include "driver/config/rule_pattern.h"

#include <set>
#include <vector>

#include "base/did_you_mean.h"
#include "diag/rule_catalog.h"
#include "diag/rule_renames.h"

namespace shaderport::driver {
namespace {

bool IsIdWord(std::string_view word) {
  if (word.empty() || word.front() == '-' || word.back() == '-') return false;
  for (char c : word) {
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-')) return false;
  }
  return true;
}

}  // namespace

bool IsValidRulePattern(std::string_view pattern) {
  if (pattern == "*") return true;
  const size_t slash = pattern.find('/');
  if (slash == std::string_view::npos) return false;
  const std::string_view category = pattern.substr(0, slash);
  const std::string_view name = pattern.substr(slash + 1);
  return IsIdWord(category) && (name == "*" || IsIdWord(name));
}

bool RulePatternMatches(std::string_view pattern, std::string_view rule_id) {
  if (pattern == "*") return true;
  // A renamed rule answers to its old id too (diag/rule_renames.def): configurations and
  // suppression comments written before the rename keep working.
  const std::string_view first_id = FirstRuleId(rule_id);
  if (pattern.size() >= 2 && pattern.substr(pattern.size() - 2) == "/*") {
    const std::string_view prefix = pattern.substr(0, pattern.size() - 1);  // "category/"
    return rule_id.starts_with(prefix) || first_id.starts_with(prefix);
  }
  return pattern == rule_id || pattern == first_id;
}

int RulePatternSpecificity(std::string_view pattern) {
  if (pattern == "*") return 0;
  if (pattern.size() >= 2 && pattern.substr(pattern.size() - 2) == "/*") return 1;
  return 2;
}

bool RulePatternMatchesCatalog(std::string_view pattern) {
  for (const RuleDescription& rule : RuleCatalog()) {
    if (RulePatternMatches(pattern, rule.id)) return true;
  }
  return false;
}

std::optional<std::string> NearestCatalogPattern(std::string_view pattern) {
  const bool category = pattern.ends_with("/*");
  std::set<std::string> names;
  for (const RuleDescription& rule : RuleCatalog()) {
    const std::string id(rule.id);
    names.insert(category ? id.substr(0, id.find('/')) + "/*" : id);
  }
  const std::vector<std::string> candidates(names.begin(), names.end());
  return ClosestName(pattern, candidates);
}

}  // namespace shaderport::driver
