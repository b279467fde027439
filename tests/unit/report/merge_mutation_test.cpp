// `merge` reads reports that anyone can hand it: every member of a real JSON and
// SARIF report swapped for another type, removed or reshaped gives a merged report
// or a usage error, never an exception (which `merge` turned into exit 3).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "../../fuzz/json_mutations.h"
#include "golden.h"
#include "report/merge.h"

namespace shaderport {
namespace {

TEST(MergeMutation, NoMutatedReportThrows) {
  size_t runs = 0;
  size_t refused = 0;
  for (const char* name : {"sample.json", "sample.sarif"}) {
    const std::string text = testing::ReadWholeFile(std::filesystem::path(SHADERPORT_SOURCE_DIR) /
                                                    "tests/golden/report" / name);
    const nlohmann::json plain = nlohmann::json::parse(text);
    for (const auto& at : fuzz::AllPointers(plain)) {
      for (const auto mutation : {fuzz::JsonMutation::kTypeSwap, fuzz::JsonMutation::kRemoveMember,
                                  fuzz::JsonMutation::kWrongShape}) {
        // Three type swaps (a string, a number, an object) keep the run short.
        for (const uint64_t variant : {0, 1, 11}) {
          if (mutation != fuzz::JsonMutation::kTypeSwap && variant != 0) continue;
          nlohmann::json mutated = plain;
          if (!fuzz::MutateAt(mutated, at, mutation, variant)) continue;
          ++runs;
          MergeResult merged;
          ASSERT_NO_THROW(merged = MergeReports({{"a", mutated.dump()}}, std::nullopt))
              << name << " " << at.to_string();
          refused += merged.errors.empty() ? 0 : 1;
        }
      }
    }
  }
  EXPECT_GT(runs, 100u);
  std::printf("%zu mutated reports, %zu refused, none threw\n", runs, refused);
}

}  // namespace
}  // namespace shaderport
