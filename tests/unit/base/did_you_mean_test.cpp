#include "base/did_you_mean.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace shaderport {
namespace {

TEST(EditDistance, CountsInsertionsDeletionsSubstitutionsAndSwaps) {
  EXPECT_EQ(EditDistance("check", "check"), 0u);
  EXPECT_EQ(EditDistance("chek", "check"), 1u);
  EXPECT_EQ(EditDistance("checkk", "check"), 1u);
  EXPECT_EQ(EditDistance("cheek", "check"), 1u);
  EXPECT_EQ(EditDistance("chcek", "check"), 1u);  // a swap is one edit
  EXPECT_EQ(EditDistance("JSON", "json"), 0u);
  EXPECT_EQ(EditDistance("", "abc"), 3u);
  EXPECT_EQ(EditDistance("render", "report"), 4u);
}

TEST(ClosestName, SuggestsOnlyNearNames) {
  const std::vector<std::string> commands = {"check", "fix", "port", "render", "report"};
  EXPECT_EQ(ClosestName("chek", commands), "check");
  EXPECT_EQ(ClosestName("prot", commands), "port");
  EXPECT_EQ(ClosestName("fxi", commands), "fix");
  EXPECT_EQ(ClosestName("lint", commands), std::nullopt);
  EXPECT_EQ(ClosestName("check", commands), std::nullopt);  // not a typo
  // An abbreviation of exactly one name.
  const std::vector<std::string> levels = {"error", "warning", "note"};
  EXPECT_EQ(ClosestName("warn", levels), "warning");
  EXPECT_EQ(ClosestName("w", levels), std::nullopt);
  EXPECT_EQ(ClosestName("re", commands), std::nullopt);  // render or report
  // Equally near: the first candidate wins.
  EXPECT_EQ(ClosestName("rep", std::vector<std::string>{"rap", "rip"}), "rap");
}

}  // namespace
}  // namespace shaderport
