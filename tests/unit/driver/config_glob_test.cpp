#include <gtest/gtest.h>

#include <string>

#include "driver/config/glob.h"
#include "driver/config/rule_pattern.h"

namespace shaderport::driver {
namespace {

TEST(ConfigGlob, StarStaysInOneSegment) {
  EXPECT_TRUE(GlobMatches("*.frag", "a.frag"));
  EXPECT_FALSE(GlobMatches("*.frag", "dir/a.frag"));
  EXPECT_TRUE(GlobMatches("shaders/*.glsl", "shaders/x.glsl"));
  EXPECT_FALSE(GlobMatches("shaders/*.glsl", "shaders/sub/x.glsl"));
  EXPECT_FALSE(GlobMatches("*.frag", "a.vert"));
}

TEST(ConfigGlob, GlobStarCrossesSegments) {
  EXPECT_TRUE(GlobMatches("shaders/**", "shaders/a.frag"));
  EXPECT_TRUE(GlobMatches("shaders/**", "shaders/x/y/a.frag"));
  EXPECT_FALSE(GlobMatches("shaders/**", "other/a.frag"));
  EXPECT_FALSE(GlobMatches("shaders/**", "shadersx/a.frag"));
  EXPECT_TRUE(GlobMatches("**/*.gen.glsl", "a.gen.glsl"));  // "**/" matches no directory too
  EXPECT_TRUE(GlobMatches("**/*.gen.glsl", "x/y/a.gen.glsl"));
  EXPECT_FALSE(GlobMatches("**/*.gen.glsl", "x/y/a.glsl"));
  EXPECT_TRUE(GlobMatches("a/**/b.frag", "a/b.frag"));
  EXPECT_TRUE(GlobMatches("a/**/b.frag", "a/x/y/b.frag"));
  EXPECT_FALSE(GlobMatches("a/**/b.frag", "a/xb.frag"));
  EXPECT_TRUE(GlobMatches("third_party/**", "third_party/lib/x.glsl"));
}

TEST(ConfigGlob, QuestionMarkAndAnchors) {
  EXPECT_TRUE(GlobMatches("a?.frag", "ab.frag"));
  EXPECT_FALSE(GlobMatches("a?.frag", "a/.frag"));
  EXPECT_FALSE(GlobMatches("a?.frag", "a.frag"));
  EXPECT_TRUE(GlobMatches("/toy/*.frag", "toy/a.frag"));
  EXPECT_TRUE(GlobMatches("exact.frag", "exact.frag"));
  EXPECT_FALSE(GlobMatches("exact.frag", "exact.frag2"));
}

TEST(ConfigGlob, HostilePatternsStayFast) {
  // Backtracking matchers take exponential time here; this one is quadratic.
  const std::string path(5000, 'a');
  EXPECT_FALSE(GlobMatches("*a*a*a*a*a*a*a*a*a*a*a*a*b", path));
  EXPECT_FALSE(GlobMatches("**a**a**a**a**a**a**b", path));
}

TEST(ConfigGlob, Errors) {
  EXPECT_EQ(GlobError("shaders/**"), "");
  EXPECT_NE(GlobError(""), "");
  EXPECT_NE(GlobError("a/***"), "");
  EXPECT_NE(GlobError("../x"), "");
  EXPECT_NE(GlobError("a\\b"), "");
}

TEST(RulePattern, FormsAndSpecificity) {
  EXPECT_TRUE(IsValidRulePattern("glslang/missing-precision"));
  EXPECT_TRUE(IsValidRulePattern("suppression/*"));
  EXPECT_TRUE(IsValidRulePattern("*"));
  EXPECT_FALSE(IsValidRulePattern("glslang"));
  EXPECT_FALSE(IsValidRulePattern("Glslang/x"));
  EXPECT_FALSE(IsValidRulePattern("a/b/c"));
  EXPECT_FALSE(IsValidRulePattern("a/-b"));
  EXPECT_FALSE(IsValidRulePattern("*/x"));
  EXPECT_TRUE(RulePatternMatches("input/*", "input/empty"));
  EXPECT_FALSE(RulePatternMatches("input/*", "inputs/empty"));
  EXPECT_TRUE(RulePatternMatches("*", "x/y"));
  EXPECT_FALSE(RulePatternMatches("input/empty", "input/empty-ish"));
  EXPECT_LT(RulePatternSpecificity("*"), RulePatternSpecificity("a/*"));
  EXPECT_LT(RulePatternSpecificity("a/*"), RulePatternSpecificity("a/b"));
  EXPECT_TRUE(RulePatternMatchesCatalog("input/*"));
  EXPECT_FALSE(RulePatternMatchesCatalog("nosuchcategory/*"));
}

}  // namespace
}  // namespace shaderport::driver
