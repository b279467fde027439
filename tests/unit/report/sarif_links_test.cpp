// The links SARIF carries: the tool's informationUri and each rule's helpUri,
// with the anchors GitHub gives the headings of docs/rules.md.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "report/docs_links.h"
#include "report/fingerprint.h"
#include "report/sarif_format.h"

namespace shaderport {
namespace {

using nlohmann::json;

TEST(DocsLinks, AnchorsAreGithubs) {
  EXPECT_EQ(GithubHeadingAnchor("port/version"), "portversion");
  EXPECT_EQ(GithubHeadingAnchor("Every diagnostic id"), "every-diagnostic-id");
  EXPECT_EQ(GithubHeadingAnchor("typing/int-literal-for-float"), "typingint-literal-for-float");
  EXPECT_EQ(GithubHeadingAnchor("A `?:` on_x (2)"), "a--on_x-2");
}

// Every heading of docs/rules.md, as anchors.
std::set<std::string> RulesPageAnchors() {
  std::ifstream in(std::string(SHADERPORT_SOURCE_DIR) + "/docs/rules.md");
  std::set<std::string> anchors;
  bool in_code = false;
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("```")) in_code = !in_code;
    if (in_code || !line.starts_with("#")) continue;
    anchors.insert(GithubHeadingAnchor(line.substr(line.find_first_not_of('#') + 1)));
  }
  return anchors;
}

TEST(DocsLinks, HelpUrisPointAtHeadingsOfTheRulesPage) {
  const std::set<std::string> anchors = RulesPageAnchors();
  for (const auto& [id, has_section] :
       {std::pair{"port/version", true}, std::pair{"typing/float-index", true},
        std::pair{"glslang/type-mismatch", false}}) {
    const std::string uri = RuleHelpUri(id, has_section);
    EXPECT_TRUE(uri.starts_with(std::string(kRepositoryUri) + "/blob/main/docs/rules.md#")) << uri;
    EXPECT_TRUE(anchors.contains(uri.substr(uri.find('#') + 1))) << uri;
  }
  EXPECT_TRUE(RuleHelpUri("glslang/type-mismatch", false).ends_with("#every-diagnostic-id"));
}

TEST(SarifLinks, DriverAndRulesCarryTheirDocs) {
  SourceManager sources;
  const SourceFile& file = sources.Add("a.frag", "#version 310 es\nx;\n");
  CheckReport report;
  report.sources = &sources;
  report.files.push_back(
      {&file,
       "webgl2",
       "fragment",
       {MakeDiagnostic(Severity::kError, "port/version", {file.Id(), 0, 15}, "m"),
        MakeDiagnostic(Severity::kError, "input/empty", {}, "m"),
        MakeDiagnostic(Severity::kError, "not-in/the-catalog", {}, "m")}});
  ReportOptions options;
  options.rules_with_sections = {"port/version", "typing/float-index"};  // sorted
  json sarif = ReportToSarif(report, options);
  const json& driver = sarif["runs"][0]["tool"]["driver"];
  EXPECT_EQ(driver["informationUri"], std::string(kRepositoryUri));
  const json& rules = driver["rules"];
  ASSERT_EQ(rules.size(), 3u);
  EXPECT_EQ(rules[0]["id"], "input/empty");
  EXPECT_TRUE(rules[0]["helpUri"].get<std::string>().ends_with("#every-diagnostic-id"));
  EXPECT_EQ(rules[1]["id"], "not-in/the-catalog");
  EXPECT_FALSE(rules[1].contains("helpUri"));
  EXPECT_EQ(rules[2]["helpUri"],
            std::string(kRepositoryUri) + "/blob/main/docs/rules.md#portversion");
  for (const json& result : sarif["runs"][0]["results"]) {
    EXPECT_TRUE(result["partialFingerprints"].contains(kFingerprintKey));
  }
  // An empty informationUri still names the project.
  options.information_uri.clear();
  sarif = ReportToSarif(report, options);
  EXPECT_EQ(sarif["runs"][0]["tool"]["driver"]["informationUri"], std::string(kRepositoryUri));
}

}  // namespace
}  // namespace shaderport
