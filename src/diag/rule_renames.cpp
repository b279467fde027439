#include "diag/rule_renames.h"

#include <array>
#include <utility>

namespace shaderport {
namespace {

constexpr std::array kRenames = {
#define RULE_RENAMED(old_id, new_id) std::pair<std::string_view, std::string_view>{old_id, new_id},
#include "diag/rule_renames.def"
#undef RULE_RENAMED
};

}  // namespace

std::string_view CurrentRuleId(std::string_view id) {
  for (const auto& [old_id, new_id] : kRenames) {
    if (old_id == id) return new_id;
  }
  return id;
}

std::string_view FirstRuleId(std::string_view id) {
  for (const auto& [old_id, new_id] : kRenames) {
    if (new_id == id) return old_id;
  }
  return id;
}

}  // namespace shaderport
