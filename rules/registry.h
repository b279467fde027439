// All rules, in the order of rules/rules.def. That order is also fix priority: when two
// fixes overlap, the rule listed earlier wins.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "rule/rule.h"

namespace shaderport::rules {

// All rules, in rules/rules.def order. Built once; the rules are immutable singletons.
std::span<const rule::Rule* const> AllRules();

// The rules that run in `mode`: kPort runs every porting rule, kFix only kAlways ones.
std::vector<const rule::Rule*> RulesForMode(rule::PortMode mode);

// The rules `shaderport check` runs beside glslang (scopes kCheck and kLint).
std::vector<const rule::Rule*> CheckRules();

// The rule with this id, or nullptr.
const rule::Rule* FindRule(std::string_view id);

}  // namespace shaderport::rules
