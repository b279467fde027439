// Behaviour of the output formats that goldens would only show indirectly.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "report/fingerprint.h"
#include "report/github_format.h"
#include "report/json_format.h"
#include "report/output_format.h"
#include "report/sarif_format.h"
#include "report/source_position.h"
#include "report/text_format.h"
#include "report_sample.h"

namespace shaderport {
namespace {

using nlohmann::json;

struct OneFile {
  SourceManager sources;
  CheckReport report;
  ReportOptions options;

  explicit OneFile(std::string text, std::string name = "a.frag") {
    const SourceFile& file = sources.Add(std::move(name), std::move(text));
    report.sources = &sources;
    report.files.push_back({&file, "webgl2", "fragment", {}});
  }
  void Add(Severity severity, uint32_t begin, uint32_t end, std::string rule = "x/y",
           std::string message = "m") {
    Diagnostic d;
    d.severity = severity;
    d.rule_id = std::move(rule);
    d.range = {0, begin, end};
    d.message = std::move(message);
    report.files[0].diagnostics.push_back(std::move(d));
  }
};

TEST(SourcePosition, Utf16ColumnsCountSurrogatePairs) {
  EXPECT_EQ(Utf16Column("abc", 1), 1u);
  EXPECT_EQ(Utf16Column("abc", 4), 4u);
  EXPECT_EQ(Utf16Column("\xC3\xA9x", 3), 2u);          // é is 2 bytes, 1 unit
  EXPECT_EQ(Utf16Column("\xE2\x82\xACx", 4), 2u);      // € is 3 bytes, 1 unit
  EXPECT_EQ(Utf16Column("\xF0\x9F\x8E\xA8x", 5), 3u);  // 🎨 is 4 bytes, 2 units
  EXPECT_EQ(Utf16Column("\xFF\xFEx", 3), 3u);          // invalid bytes: one unit each
  EXPECT_EQ(Utf16Column("\xF0\x9F", 3), 3u);           // truncated sequence
  EXPECT_EQ(Utf16Column("ab", 99), 3u);                // clamped to the line
}

TEST(SourcePosition, DisplayPathIsRelativeToTheBase) {
  EXPECT_EQ(DisplayPath("/work/p/a/b.frag", "/work/p"), "a/b.frag");
  EXPECT_EQ(DisplayPath("/work/p/a/b.frag", "/work/p/"), "a/b.frag");
  EXPECT_EQ(DisplayPath("/work/pq/b.frag", "/work/p"), "/work/pq/b.frag");
  EXPECT_EQ(DisplayPath("./x/./y.frag", ""), "x/./y.frag");
  EXPECT_EQ(DisplayPath("a\\b.frag", ""), "a/b.frag");
  EXPECT_EQ(EncodeUriPath("a b/c%,d.frag"), "a%20b/c%25%2Cd.frag");
}

TEST(SourcePosition, BadRangesAreClampedNotTrusted) {
  SourceManager sources;
  sources.Add("a", "abc\ndef");
  EXPECT_FALSE(Resolve(&sources, {}).has_value());
  EXPECT_FALSE(Resolve(&sources, {7, 0, 1}).has_value());  // unknown file
  EXPECT_FALSE(Resolve(nullptr, {0, 0, 1}).has_value());
  auto past_end = Resolve(&sources, {0, 5, 100});
  ASSERT_TRUE(past_end);
  EXPECT_EQ(past_end->end_offset, 7u);
  auto reversed = Resolve(&sources, {0, 3, 1});
  ASSERT_TRUE(reversed);
  EXPECT_EQ(reversed->begin_offset, reversed->end_offset);
}

TEST(TextFormat, CaretKeepsTabsAndCountsCharacters) {
  OneFile one("\t\xC3\xA9t\xC3\xA9 = x;\n");
  one.Add(Severity::kError, 1, 6);  // "été"
  const std::string text = FormatText(one.report, one.options);
  EXPECT_NE(text.find("a.frag:1:2: error: m [x/y]\n"), std::string::npos) << text;
  EXPECT_NE(text.find("      | \t^~~\n"), std::string::npos) << text;
}

// A 4 MB one-line document with a thousand findings printed the whole line for
// each (4 GB of output); a long line is shown as a window around the finding.
TEST(TextFormat, LongLinesAreShownAsAWindowAroundTheFinding) {
  std::string line(5000, 'a');
  line.replace(3000, 3, "XYZ");
  OneFile one(line + "\n");
  one.Add(Severity::kError, 3000, 3003);
  const std::string text = FormatText(one.report, one.options);
  const size_t shown = text.find("    1 | ...");
  ASSERT_NE(shown, std::string::npos) << text;
  const size_t shown_end = text.find('\n', shown);
  EXPECT_LT(shown_end - shown, 260u);
  EXPECT_EQ(text.substr(shown_end - 3, 3), "...");
  // The caret stands under X in the window shown.
  const size_t caret_line = shown_end + 1;
  const size_t caret = text.find('^', caret_line);
  EXPECT_EQ(caret - caret_line, text.find("XYZ", shown) - shown);
  EXPECT_EQ(text.substr(caret, 3), "^~~");
  // A line of normal length is shown whole.
  OneFile normal(std::string(1000, 'b') + "\n");
  normal.Add(Severity::kError, 900, 901);
  EXPECT_NE(FormatText(normal.report, normal.options).find(std::string(1000, 'b')),
            std::string::npos);
}

TEST(TextFormat, ColourOnlyWhenAsked) {
  OneFile one("x;\n");
  one.Add(Severity::kWarning, 0, 1);
  EXPECT_EQ(FormatText(one.report, one.options).find('\x1b'), std::string::npos);
  one.options.color = true;
  const std::string coloured = FormatText(one.report, one.options);
  EXPECT_NE(coloured.find("\x1b[1;35mwarning:"), std::string::npos) << coloured;
  EXPECT_NE(coloured.find("\x1b[1;32m^"), std::string::npos) << coloured;
}

TEST(TextFormat, ControlBytesInSourceDoNotReachTheTerminal) {
  OneFile one("a\x1b[31m;\n");
  one.Add(Severity::kError, 0, 1);
  EXPECT_EQ(FormatText(one.report, one.options).find('\x1b'), std::string::npos);
}

TEST(TextFormat, SummaryCountsAndPlurals) {
  EXPECT_EQ(SummaryLine({1, 1, 0, 1, 1}), "1 error, 1 warning in 1 file (1 file checked)");
  EXPECT_EQ(SummaryLine({0, 2, 3, 2, 5}),
            "0 errors, 2 warnings, 3 notes in 2 files (5 files checked)");
  OneFile one("x;\ny;\n");
  one.Add(Severity::kError, 0, 1);
  one.Add(Severity::kError, 3, 4);
  one.Add(Severity::kWarning, 3, 4);
  const ReportSummary summary = Summarize(one.report);
  EXPECT_EQ(summary.errors, 2u);
  EXPECT_EQ(summary.warnings, 1u);
  EXPECT_EQ(summary.files_with_problems, 1u);
}

TEST(JsonFormat, RangesHaveLinesColumnsAndOffsets) {
  OneFile one("ab\n\xC3\xA9xyz\n");
  one.Add(Severity::kWarning, 5, 8, "r/one", "msg");
  const json doc = json::parse(FormatJson(one.report, one.options));
  EXPECT_EQ(doc["version"], 1);
  EXPECT_EQ(doc["tool"]["name"], "shaderport");
  const json& d = doc["files"][0]["diagnostics"][0];
  EXPECT_EQ(d["severity"], "warning");
  EXPECT_EQ(d["rule"], "r/one");
  EXPECT_EQ(d["location"]["range"]["start"], json({{"line", 2}, {"column", 3}, {"offset", 5}}));
  EXPECT_EQ(d["location"]["range"]["end"], json({{"line", 2}, {"column", 6}, {"offset", 8}}));
  EXPECT_EQ(doc["summary"]["warnings"], 1);
}

TEST(JsonFormat, InvalidUtf8DoesNotThrow) {
  OneFile one("x\n");
  one.Add(Severity::kError, 0, 1, "r/x", "bad \xFF byte");
  EXPECT_NO_THROW(json::parse(FormatJson(one.report, one.options)));
}

TEST(SarifFormat, RulesAreSortedAndIndexed) {
  testing::ReportSample sample;
  const json sarif = json::parse(FormatSarif(sample.report, sample.options));
  EXPECT_EQ(sarif["version"], "2.1.0");
  const json& run = sarif["runs"][0];
  const json& rules = run["tool"]["driver"]["rules"];
  for (size_t i = 1; i < rules.size(); ++i) {
    EXPECT_LT(rules[i - 1]["id"].get<std::string>(), rules[i]["id"].get<std::string>());
  }
  for (const json& result : run["results"]) {
    EXPECT_EQ(rules[result["ruleIndex"].get<size_t>()]["id"], result["ruleId"]);
    EXPECT_TRUE(result["partialFingerprints"].contains(kFingerprintKey));
  }
}

TEST(SarifFormat, CatalogTextAndStrongestLevel) {
  OneFile one("x;\n");
  one.Add(Severity::kWarning, 0, 1, "input/empty");
  one.Add(Severity::kError, 0, 1, "input/empty");
  const json sarif = ReportToSarif(one.report, one.options);
  const json& rule = sarif["runs"][0]["tool"]["driver"]["rules"][0];
  EXPECT_EQ(rule["shortDescription"]["text"], "The file is empty");
  EXPECT_EQ(rule["defaultConfiguration"]["level"], "error");
  EXPECT_FALSE(rule["help"]["text"].get<std::string>().empty());
}

TEST(SarifFormat, RegionColumnsAreUtf16AndEndExclusive) {
  OneFile one("\xF0\x9F\x8E\xA8 ab\n", "dir/x y.frag");
  one.Add(Severity::kNote, 5, 7);  // "ab" after an emoji and a space
  const json result = ReportToSarif(one.report, one.options)["runs"][0]["results"][0];
  const json& location = result["locations"][0]["physicalLocation"];
  EXPECT_EQ(location["artifactLocation"]["uri"], "dir/x%20y.frag");
  EXPECT_EQ(location["artifactLocation"]["uriBaseId"], kSarifSourceRoot);
  EXPECT_EQ(location["region"]["startColumn"], 4);
  EXPECT_EQ(location["region"]["endColumn"], 6);
  EXPECT_EQ(result["level"], "note");
}

TEST(SarifFormat, RepeatedFindingsGetDistinctFingerprints) {
  OneFile one("x;\nx;\n");
  one.Add(Severity::kError, 0, 1);
  one.Add(Severity::kError, 3, 4);
  const json results = ReportToSarif(one.report, one.options)["runs"][0]["results"];
  EXPECT_NE(results[0]["partialFingerprints"], results[1]["partialFingerprints"]);
}

TEST(SarifFormat, AbsolutePathOutsideTheBaseIsAFileUri) {
  OneFile one("x;\n", "/elsewhere/a b.frag");
  one.options.base_directory = "/work";
  one.Add(Severity::kError, 0, 1);
  const json sarif = ReportToSarif(one.report, one.options);
  EXPECT_EQ(sarif["runs"][0]["originalUriBaseIds"][kSarifSourceRoot]["uri"], "file:///work/");
  EXPECT_EQ(
      sarif["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["artifactLocation"]["uri"],
      "file:///elsewhere/a%20b.frag");
}

TEST(GithubFormat, EscapesDataAndProperties) {
  EXPECT_EQ(EscapeGithubData("a%b\r\nc:d,e"), "a%25b%0D%0Ac:d,e");
  EXPECT_EQ(EscapeGithubProperty("a%b\r\nc:d,e"), "a%25b%0D%0Ac%3Ad%2Ce");
  OneFile one("abc\n", "we:ird,name.frag");
  one.Add(Severity::kNote, 1, 3, "r/x", "50%\ndone");
  EXPECT_EQ(FormatGithub(one.report, one.options),
            "::notice file=we%3Aird%2Cname.frag,line=1,col=2,endLine=1,endColumn=3,title=r/x::"
            "50%25%0Adone\n");
}

TEST(OutputFormat, NamesRoundTrip) {
  for (OutputFormat format :
       {OutputFormat::kText, OutputFormat::kJson, OutputFormat::kSarif, OutputFormat::kGithub}) {
    EXPECT_EQ(ParseOutputFormat(OutputFormatName(format)), format);
  }
  EXPECT_FALSE(ParseOutputFormat("xml").has_value());
}

TEST(OutputFormat, EmptyReportStillPrintsValidDocuments) {
  SourceManager sources;
  CheckReport report{{}, &sources};
  ReportOptions options;
  EXPECT_EQ(FormatText(report, options), "0 errors, 0 warnings in 0 files (0 files checked)\n");
  EXPECT_EQ(json::parse(FormatSarif(report, options))["runs"][0]["results"].size(), 0u);
  EXPECT_EQ(FormatGithub(report, options), "");
}

TEST(OutputFormat, AnyRangeIsPrintedWithoutCrashing) {
  // Producers have bugs: ranges past the end, reversed, in unknown files, inside
  // multi-byte characters, on CR LF lines. Every format must still print something.
  OneFile one(
      "a\t\xC3\xA9\r\n\xF0\x9F\x8E\xA8"
      "b\rc\n\xFF");
  const uint32_t size = 14;
  uint32_t seed = 12345;
  auto next = [&seed] { return seed = seed * 1103515245u + 12345u; };
  for (int i = 0; i < 400; ++i) {
    Diagnostic d;
    d.rule_id = "r/x";
    d.range = {next() % 5 == 0 ? 3u : 0u, next() % (size + 3), next() % (size + 3)};
    d.notes.push_back({{next() % 4 == 0 ? kNoFile : 0u, next() % size, next() % size}, "n"});
    d.fixes.push_back({{0, next() % size, next() % size}, "x\ny", FixSafety::kSafe});
    one.report.files[0].diagnostics.push_back(std::move(d));
  }
  for (OutputFormat format :
       {OutputFormat::kText, OutputFormat::kJson, OutputFormat::kSarif, OutputFormat::kGithub}) {
    EXPECT_FALSE(FormatReport(one.report, format, one.options).empty());
  }
}

}  // namespace
}  // namespace shaderport
