// Renamed rule ids (src/diag/rule_renames.def: webgl2/* became port/*) stay aliases:
// configurations, suppression comments and `explain` written with the old id keep working.
#include <gtest/gtest.h>

#include <string>

#include "diag/rule_renames.h"
#include "driver/config/rule_pattern.h"
#include "driver/port/rule_reference.h"

namespace shaderport::driver {
namespace {

TEST(RuleAlias, OldIdsAndCategoriesStillMatchTheRenamedRule) {
  EXPECT_EQ(CurrentRuleId("webgl2/version"), "port/version");
  EXPECT_EQ(FirstRuleId("port/version"), "webgl2/version");
  EXPECT_EQ(CurrentRuleId("webgl/version"), "webgl/version");  // a browser check, not renamed
  EXPECT_TRUE(RulePatternMatches("webgl2/version", "port/version"));
  EXPECT_TRUE(RulePatternMatches("webgl2/*", "port/precision"));
  EXPECT_TRUE(RulePatternMatches("port/*", "port/precision"));
  EXPECT_FALSE(RulePatternMatches("webgl2/*", "port/stages-do-not-link"));  // never webgl2/*
  EXPECT_FALSE(RulePatternMatches("webgl2/version", "webgl/version"));
  EXPECT_TRUE(RulePatternMatchesCatalog("webgl2/*"));
  EXPECT_TRUE(RulePatternMatchesCatalog("webgl2/texture-functions"));
}

TEST(RuleAlias, ExplainingAnOldIdExplainsTheRuleItBecame) {
  const auto old_id = ExplainRule("webgl2/version");
  ASSERT_TRUE(old_id.has_value());
  EXPECT_EQ(*old_id, *ExplainRule("port/version"));
  EXPECT_TRUE(old_id->starts_with("## port/version")) << *old_id;
}

}  // namespace
}  // namespace shaderport::driver
