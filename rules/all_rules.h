// Every porting rule's factory, one line each, sorted by rule id.
//
// To add a rule: define `const rule::Rule& FooRule();` in its own file under
// rules/ (namespace shaderport::rules), add ONE line below at its sorted place,
// and ONE line in rules/registry.cpp. Keep both lists sorted by rule id.
#pragma once

#include "rule/rule.h"

namespace shaderport::rules {

// clang-format off
// ---- rule factories (sorted by rule id; one line per rule) ----
// ---- end of rule factories ----
// clang-format on

}  // namespace shaderport::rules
