// rules/rules.def is the one registration list: each line's id is its rule's own, and
// has a catalog row; the order it gives is the registry's (fix priority).
#include "rules/registry.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "diag/rule_catalog.h"
#include "rules/all_rules.h"

namespace shaderport::rules {
namespace {

struct Line {
  const rule::Rule* rule;
  std::string_view id;
};

const std::vector<Line>& Lines() {
  static const std::vector<Line> lines = {
#define RULE_FACTORY(factory, id) {&factory(), id},
#include "rules/rules.def"
#undef RULE_FACTORY
  };
  return lines;
}

TEST(RuleRegistry, EveryLineNamesItsRulesOwnIdWithACatalogRow) {
  std::set<std::string_view> seen;
  for (const Line& line : Lines()) {
    EXPECT_EQ(line.rule->Info().id, line.id);
    EXPECT_TRUE(seen.insert(line.id).second) << line.id << " is registered twice";
    EXPECT_NE(shaderport::FindRule(line.id), nullptr) << line.id << " has no catalog row";
  }
}

TEST(RuleRegistry, RegistryOrderIsTheListsOrder) {
  const auto all = AllRules();
  ASSERT_EQ(all.size(), Lines().size());
  for (size_t i = 0; i < all.size(); ++i) EXPECT_EQ(all[i], Lines()[i].rule) << Lines()[i].id;
}

}  // namespace
}  // namespace shaderport::rules
