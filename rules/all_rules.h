// Every rule's factory, declared from rules/rules.def (one line a rule).
#pragma once

#include "rule/rule.h"

namespace shaderport::rules {

#define RULE_FACTORY(factory, id) const rule::Rule& factory();
#include "rules/rules.def"
#undef RULE_FACTORY

}  // namespace shaderport::rules
