// The baseline file and matching findings against it.
#include "report/baseline.h"

#include <gtest/gtest.h>

#include <string>

namespace shaderport {
namespace {

// A report of one file with a warning on every line that holds "bad".
struct BadLines {
  SourceManager sources;
  CheckReport report;

  explicit BadLines(const std::string& text, const std::string& name = "/repo/s/a.frag") {
    const SourceFile& file = sources.Add(name, text);
    report.sources = &sources;
    FileReport file_report{&file, "webgl2", "fragment", {}, Severity::kWarning};
    for (size_t at = text.find("bad"); at != std::string::npos; at = text.find("bad", at + 1)) {
      const auto begin = static_cast<uint32_t>(at);
      file_report.diagnostics.push_back(MakeDiagnostic(
          Severity::kWarning, "x/bad", {file.Id(), begin, begin + 3}, "'bad' is bad"));
    }
    report.files.push_back(std::move(file_report));
  }
};

TEST(Baseline, FileIsSortedVersionedAndRoundTrips) {
  BadLines lines("a;\nbad;\nb;\nbad;\n");
  const Baseline baseline = BaselineOfReport(lines.report, "/repo");
  ASSERT_EQ(baseline.entries.size(), 2u);
  EXPECT_EQ(baseline.entries[0].path, "s/a.frag");
  EXPECT_EQ(baseline.entries[0].rule, "x/bad");
  EXPECT_EQ(baseline.entries[0].message, "'bad' is bad");
  EXPECT_LT(baseline.entries[0].fingerprint, baseline.entries[1].fingerprint);
  const std::string text = FormatBaseline(baseline);
  EXPECT_EQ(
      text.rfind("{\n  \"version\": 1,\n  \"findings\": [\n    {\n      \"fingerprint\": ", 0), 0u)
      << text;
  std::string error;
  const auto parsed = ParseBaseline(text, error);
  ASSERT_TRUE(parsed) << error;
  EXPECT_EQ(parsed->entries, baseline.entries);
  EXPECT_EQ(FormatBaseline(*parsed), text);
}

TEST(Baseline, BadFilesAreRejectedWithAReason) {
  const char* const bad[] = {
      "",
      "{",
      "[]",
      R"({"findings": []})",
      R"({"version": 2, "findings": []})",
      R"({"version": "1", "findings": []})",
      R"({"version": 1})",
      R"({"version": 1, "findings": {}})",
      R"({"version": 1, "findings": [{"rule": "x/y"}]})",
      R"({"version": 1, "findings": [{"fingerprint": 7}]})",
      R"({"version": 1, "findings": [{"fingerprint": "f:1", "message": null}]})",
      R"({"version": 1, "findings": ["f:1"]})",
  };
  for (const char* text : bad) {
    std::string error;
    EXPECT_FALSE(ParseBaseline(text, error)) << text;
    EXPECT_FALSE(error.empty()) << text;
  }
  std::string error;
  const auto minimal =
      ParseBaseline(R"({"version": 1, "findings": [{"fingerprint": "f:1"}]})", error);
  ASSERT_TRUE(minimal) << error;
  EXPECT_EQ(minimal->entries.at(0).fingerprint, "f:1");
}

TEST(Baseline, KnownFindingsAreDroppedNewOnesKeptFixedOnesListed) {
  BadLines before("a;\nbad;\nb;\nbad();\n");
  const Baseline baseline = BaselineOfReport(before.report, "/repo");
  // Lines added above move both findings; the first is fixed; a new one appears.
  BadLines after("bad + 1;\n// new\n\na;\nfine;\nb;\nbad();\n");
  const BaselineOutcome outcome = ApplyBaseline(after.report, baseline, "/repo");
  EXPECT_EQ(outcome.baselined, 1u);
  ASSERT_EQ(after.report.files[0].diagnostics.size(), 1u);
  EXPECT_EQ(after.sources.Get(0).LocationOf(after.report.files[0].diagnostics[0].range.begin).line,
            1u);
  ASSERT_EQ(outcome.fixed.size(), 1u);
  EXPECT_EQ(outcome.fixed[0].fingerprint,
            BaselineOfReport(BadLines("a;\nbad;\nb;\n").report, "/repo").entries.at(0).fingerprint);
  EXPECT_EQ(FormatBaselineSummary(outcome),
            "1 finding in the baseline was not reported; 1 baseline entry is fixed; rewrite the "
            "baseline with --write-baseline\n");
}

TEST(Baseline, RepeatsBeyondTheBaselinedCountAreNew) {
  // The same line between the same neighbours: told apart by occurrence only.
  BadLines two("x;\nbad;\nx;\nbad;\nx;\n");
  const Baseline baseline = BaselineOfReport(two.report, "");
  BadLines three("x;\nbad;\nx;\nbad;\nx;\nbad;\nx;\n");
  const BaselineOutcome outcome = ApplyBaseline(three.report, baseline, "");
  EXPECT_EQ(outcome.baselined, 2u);
  EXPECT_EQ(three.report.files[0].diagnostics.size(), 1u);
  EXPECT_TRUE(outcome.fixed.empty());
  EXPECT_TRUE(ReportFails(three.report));
  // Unchanged: everything is baselined, nothing is fixed, the run passes.
  BadLines again("x;\nbad;\nx;\nbad;\nx;\n");
  const BaselineOutcome unchanged = ApplyBaseline(again.report, baseline, "");
  EXPECT_EQ(unchanged.baselined, 2u);
  EXPECT_TRUE(unchanged.fixed.empty());
  EXPECT_FALSE(ReportFails(again.report));
  EXPECT_EQ(FormatBaselineSummary(unchanged), "2 findings in the baseline were not reported\n");
}

TEST(Baseline, ReportFailsByEachFilesLevel) {
  BadLines warnings("bad;\n");
  EXPECT_TRUE(ReportFails(warnings.report));  // fail_on is warning for this file
  warnings.report.files[0].fail_on = Severity::kError;
  EXPECT_FALSE(ReportFails(warnings.report));
}

}  // namespace
}  // namespace shaderport
