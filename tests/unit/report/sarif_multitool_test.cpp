// SARIF that Microsoft's validator (Sarif.Multitool validate) accepts without errors
// or warnings: artifact URIs without "." or ".." segments (SARIF1002, and what
// GitHub resolves against the checkout) and a region in every result location
// (SARIF2017). tests/sarif/validate.py checks the same rules on whole logs.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "report/sarif_format.h"

namespace shaderport {
namespace {

using nlohmann::ordered_json;

// The first result's location in the SARIF of one file with one finding.
struct OneFinding {
  SourceManager sources;
  CheckReport report;
  ReportOptions options;

  OneFinding(std::string name, std::string base_directory, SourceRange range = {0, 0, 1}) {
    const SourceFile& file = sources.Add(std::move(name), "x;\n");
    report.sources = &sources;
    report.files.push_back(
        {&file, "webgl2", "fragment", {MakeDiagnostic(Severity::kError, "x/y", range, "m")}});
    options.base_directory = std::move(base_directory);
  }
  ordered_json Sarif() const { return ReportToSarif(report, options); }
  ordered_json Location() const {
    return Sarif()["runs"][0]["results"][0]["locations"][0]["physicalLocation"];
  }
};

ordered_json Relative(const std::string& uri) {
  return {{"uri", uri}, {"uriBaseId", kSarifSourceRoot}};
}

TEST(SarifMultitool, DotSegmentsAreResolvedBelowTheBase) {
  EXPECT_EQ(OneFinding("/work/p/a/../b/./c.frag", "/work/p").Location()["artifactLocation"],
            Relative("b/c.frag"));
  EXPECT_EQ(OneFinding("./a/./b.frag", "/work/p").Location()["artifactLocation"],
            Relative("a/b.frag"));
  // A relative name is relative to the base: "../p/x" lies below it after all.
  EXPECT_EQ(OneFinding("../p/shaders/x.frag", "/work/p").Location()["artifactLocation"],
            Relative("shaders/x.frag"));
}

TEST(SarifMultitool, FileUrisHaveNoDotDotSegments) {
  // Outside the base: an absolute file URI, never "../" against %SRCROOT%.
  EXPECT_EQ(OneFinding("../other/x.frag", "/work/p").Location()["artifactLocation"],
            ordered_json({{"uri", "file:///work/other/x.frag"}}));
  EXPECT_EQ(OneFinding("/tmp/../tmp/x.frag", "/work/p").Location()["artifactLocation"],
            ordered_json({{"uri", "file:///tmp/x.frag"}}));
  EXPECT_EQ(OneFinding("/../x.frag", "/work/p").Location()["artifactLocation"],
            ordered_json({{"uri", "file:///x.frag"}}));
  EXPECT_EQ(OneFinding("C:\\proj\\..\\x.frag", "C:/proj").Location()["artifactLocation"],
            ordered_json({{"uri", "file:///C:/x.frag"}}));
  // The base itself too (SARIF1004 rejects ".." there).
  const OneFinding in_base("/work/p/x.frag", "/work/q/../p/.");
  EXPECT_EQ(in_base.Sarif()["runs"][0]["originalUriBaseIds"][kSarifSourceRoot]["uri"],
            "file:///work/p/");
  EXPECT_EQ(in_base.Location()["artifactLocation"], Relative("x.frag"));
  // Below the root directory: "x.frag", not "//x.frag" (a network path).
  const OneFinding below_root("x.frag", "/");
  EXPECT_EQ(below_root.Sarif()["runs"][0]["originalUriBaseIds"][kSarifSourceRoot]["uri"],
            "file:///");
  EXPECT_EQ(below_root.Location()["artifactLocation"], Relative("x.frag"));
}

TEST(SarifMultitool, WithoutABaseRelativeNamesKeepTheirLeadingDotDot) {
  EXPECT_EQ(OneFinding("../a/./b/../c.frag", "").Location()["artifactLocation"],
            Relative("../a/c.frag"));
}

TEST(SarifMultitool, AFindingWithoutARangePointsAtTheStartOfTheFile) {
  const OneFinding whole_file("/work/p/x.frag", "/work/p", SourceRange{});
  EXPECT_EQ(whole_file.Location()["region"],
            ordered_json({{"startLine", 1}, {"startColumn", 1}, {"endLine", 1}, {"endColumn", 1}}));
}

}  // namespace
}  // namespace shaderport
