#include "diag/limit_breach.h"

#include <algorithm>
#include <array>

namespace shaderport {

bool IsLimitBreach(std::string_view rule_id) {
  static constexpr std::array<std::string_view, 6> kLimitRules = {
      "lex/too-many-tokens",
      "syntax/nesting-too-deep",
      "preprocessor/macro-too-deep",
      "preprocessor/expansion-too-large",
      "preprocessor/conditional-too-deep",
      "preprocessor/output-too-large"};
  return std::find(kLimitRules.begin(), kLimitRules.end(), rule_id) != kLimitRules.end();
}

bool HasLimitBreach(const DiagnosticList& diagnostics) {
  return std::any_of(diagnostics.begin(), diagnostics.end(),
                     [](const Diagnostic& d) { return IsLimitBreach(d.rule_id); });
}

DiagnosticList LimitBreaches(const DiagnosticList& diagnostics) {
  DiagnosticList breaches;
  for (const Diagnostic& d : diagnostics) {
    if (IsLimitBreach(d.rule_id)) breaches.push_back(d);
  }
  return breaches;
}

}  // namespace shaderport
