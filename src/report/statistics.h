// `check --statistics`: how many findings each rule produced, as `ruff --statistics`.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "report/check_report.h"

namespace shaderport {

struct RuleCount {
  std::string rule_id;
  size_t count = 0;
  Severity severity = Severity::kNote;  // the most severe the rule was reported at
  std::string_view summary;             // the catalog's one-line summary ("" if unlisted)
};

// One entry per rule id found in `report`, most frequent first, then by id.
std::vector<RuleCount> CountByRule(const CheckReport& report);

// One aligned line per rule: count, rule id, severity, summary. "" when empty.
std::string FormatStatistics(const std::vector<RuleCount>& counts);

}  // namespace shaderport
