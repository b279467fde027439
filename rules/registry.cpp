#include "rules/registry.h"

#include "rules/all_rules.h"

namespace shaderport::rules {
namespace {

// In rules/rules.def order, which is fix priority (rules/registry.h).
std::vector<const rule::Rule*> BuildRegistry() {
  return {
#define RULE_FACTORY(factory, id) &factory(),
#include "rules/rules.def"
#undef RULE_FACTORY
  };
}

}  // namespace

std::span<const rule::Rule* const> AllRules() {
  static const std::vector<const rule::Rule*> registry = BuildRegistry();
  return registry;
}

std::vector<const rule::Rule*> RulesForMode(rule::PortMode mode) {
  std::vector<const rule::Rule*> selected;
  for (const rule::Rule* r : AllRules()) {
    const rule::RuleScope scope = r->Info().scope;
    if (scope == rule::RuleScope::kCheck) continue;
    const bool every_mode = scope == rule::RuleScope::kAlways || scope == rule::RuleScope::kLint;
    if (mode == rule::PortMode::kPort || every_mode) selected.push_back(r);
  }
  return selected;
}

std::vector<const rule::Rule*> CheckRules() {
  std::vector<const rule::Rule*> selected;
  for (const rule::Rule* r : AllRules()) {
    const rule::RuleScope scope = r->Info().scope;
    if (scope == rule::RuleScope::kCheck || scope == rule::RuleScope::kLint) selected.push_back(r);
  }
  return selected;
}

const rule::Rule* FindRule(std::string_view id) {
  for (const rule::Rule* r : AllRules()) {
    if (r->Info().id == id) return r;
  }
  return nullptr;
}

}  // namespace shaderport::rules
