// Renamed rule ids (rule_renames.def): old ids are aliases of the new ones.
#pragma once

#include <string_view>

namespace shaderport {

// The id a rule has now: `id` itself unless it is an old id.
std::string_view CurrentRuleId(std::string_view id);

// The id a rule was first published under (what fingerprints hash): `id` itself unless
// the rule was renamed.
std::string_view FirstRuleId(std::string_view id);

}  // namespace shaderport
