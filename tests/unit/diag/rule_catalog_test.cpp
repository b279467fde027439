#include "diag/rule_catalog.h"

#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <string>

namespace shaderport {
namespace {

TEST(RuleCatalogTest, IdsAreUniqueSortedAndWellFormed) {
  const std::regex id_form("[a-z0-9]+/[a-z0-9]+(-[a-z0-9]+)*");
  std::set<std::string_view> seen;
  std::string_view previous;
  for (const RuleDescription& rule : RuleCatalog()) {
    EXPECT_TRUE(std::regex_match(std::string(rule.id), id_form)) << rule.id;
    EXPECT_TRUE(seen.insert(rule.id).second) << "duplicate " << rule.id;
    EXPECT_LT(previous, rule.id);
    previous = rule.id;
    EXPECT_FALSE(rule.summary.empty()) << rule.id;
    EXPECT_FALSE(rule.help.empty()) << rule.id;
    EXPECT_NE(rule.summary.back(), '.') << rule.id;
  }
}

TEST(RuleCatalogTest, FindsKnownIdsOnly) {
  ASSERT_NE(FindRule("input/empty"), nullptr);
  EXPECT_EQ(FindRule("input/empty")->id, "input/empty");
  EXPECT_EQ(FindRule("input/nope"), nullptr);
  EXPECT_EQ(FindRule(""), nullptr);
}

}  // namespace
}  // namespace shaderport
