// The HTML report's first screen (gallery, filters) and the folding of compiler
// cascades in the details, from report data alone.
#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "driver/html_report/html_gallery.h"
#include "driver/html_report/html_report.h"
#include "driver/html_report/report_steps.h"

namespace shaderport::driver {
namespace {

size_t Occurrences(std::string_view text, std::string_view needle) {
  size_t count = 0;
  for (size_t at = text.find(needle); at != std::string_view::npos;
       at = text.find(needle, at + needle.size())) {
    ++count;
  }
  return count;
}

// The text between `begin` and the next `end` after it ("" when absent).
std::string_view Between(std::string_view text, std::string_view begin, std::string_view end) {
  const size_t from = text.find(begin);
  if (from == std::string_view::npos) return {};
  const size_t to = text.find(end, from);
  return text.substr(from, to == std::string_view::npos ? text.npos : to - from);
}

ReportEntry Entry(std::string path, StepStatus check, StepStatus render, bool picture) {
  ReportEntry entry;
  entry.path = std::move(path);
  entry.check.status = check;
  entry.port.status = StepStatus::kPass;
  entry.render.status = render;
  if (picture) entry.png = "PNG";
  return entry;
}

// One of each tile status, in path order.
HtmlReport FourShaders() {
  HtmlReport report;
  report.entries.push_back(Entry("a-pass.glsl", StepStatus::kPass, StepStatus::kPass, true));
  report.entries.push_back(Entry("b-warn.glsl", StepStatus::kWarn, StepStatus::kPass, true));
  ReportEntry failing = Entry("c-fail.glsl", StepStatus::kFail, StepStatus::kPass, true);
  failing.check.findings = {{"c-fail.glsl:3:1: error: FIRST-FINDING [glslang/error]\n", "g"}};
  report.entries.push_back(failing);
  report.entries.push_back(Entry("d-none.glsl", StepStatus::kPass, StepStatus::kSkipped, false));
  return report;
}

TEST(HtmlReportGallery, GalleryComesBeforeSummaryAndAnyFinding) {
  const std::string html = FormatHtmlReport(FourShaders());
  const size_t gallery = html.find("<section id=\"gallery\">");
  ASSERT_NE(gallery, std::string::npos);
  EXPECT_LT(gallery, html.find("<section id=\"summary\">"));
  EXPECT_LT(gallery, html.find("<section id=\"shaders\">"));
  EXPECT_LT(gallery, html.find("FIRST-FINDING"));
  EXPECT_LT(gallery, html.find("<pre>"));
  // Nothing but the title and one meta line sits above it.
  EXPECT_LT(html.find("<h1>"), gallery);
  EXPECT_EQ(Occurrences(html.substr(0, gallery), "<pre"), 0u);
  EXPECT_EQ(Occurrences(html.substr(0, gallery), "<table"), 0u);
}

TEST(HtmlReportGallery, OneTilePerShaderWithItsStatusLinkingToItsDetails) {
  const std::string html = FormatHtmlReport(FourShaders());
  const std::string_view gallery = Between(html, "<section id=\"gallery\">", "</section>");
  EXPECT_EQ(Occurrences(gallery, "<a class=\"tile "), 4u);
  const char* const tiles[] = {
      "<a class=\"tile is-pass\" href=\"#shader-1\" title=\"a-pass.glsl\">",
      "<a class=\"tile is-warn\" href=\"#shader-2\" title=\"b-warn.glsl\">",
      "<a class=\"tile is-fail\" href=\"#shader-3\" title=\"c-fail.glsl\">",
      "<a class=\"tile is-not-rendered\" href=\"#shader-4\" title=\"d-none.glsl\">",
  };
  for (const char* tile : tiles) EXPECT_NE(gallery.find(tile), std::string::npos) << tile;
  // A failing or warning badge names the steps.
  for (const char* badge : {">passes<", ">warnings: check<", ">fails: check<", ">not rendered<"}) {
    EXPECT_EQ(Occurrences(gallery, badge), 1u) << badge;
  }
  // The thumbnail lives in the tile, once: the details do not repeat the base64.
  EXPECT_EQ(Occurrences(gallery, "src=\"data:image/png;base64,"), 3u);
  EXPECT_EQ(Occurrences(html, "src=\"data:image/png;base64,"), 3u);
  EXPECT_NE(gallery.find("<span class=\"pic\">no picture</span>"), std::string::npos);
  // Each anchor has its target, which carries the same status class for the filters.
  EXPECT_NE(html.find("<div class=\"shader is-pass\" id=\"shader-1\">"), std::string::npos);
  EXPECT_NE(html.find("<div class=\"shader is-fail\" id=\"shader-3\">"), std::string::npos);
  EXPECT_NE(html.find("<div class=\"shader is-not-rendered\" id=\"shader-4\">"), std::string::npos);
}

TEST(HtmlReportGallery, StatusIsTheWorstStepThenTheMissingPicture) {
  EXPECT_EQ(StatusOfEntry(Entry("x", StepStatus::kPass, StepStatus::kPass, true)),
            EntryStatus::kPass);
  EXPECT_EQ(StatusOfEntry(Entry("x", StepStatus::kPass, StepStatus::kWarn, true)),
            EntryStatus::kWarn);
  EXPECT_EQ(StatusOfEntry(Entry("x", StepStatus::kWarn, StepStatus::kFail, false)),
            EntryStatus::kFail);
  EXPECT_EQ(StatusOfEntry(Entry("x", StepStatus::kWarn, StepStatus::kSkipped, false)),
            EntryStatus::kWarn);
  EXPECT_EQ(StatusOfEntry(Entry("x", StepStatus::kPass, StepStatus::kSkipped, false)),
            EntryStatus::kNotRendered);
}

TEST(HtmlReportGallery, BadgeNamesEveryStepAtTheWorstStatus) {
  HtmlReport report;
  ReportEntry entry = Entry("a.glsl", StepStatus::kFail, StepStatus::kFail, false);
  entry.port.status = StepStatus::kWarn;
  report.entries.push_back(entry);
  EXPECT_NE(FormatHtmlReport(report).find("<span class=\"badge fail\">fails: check, render</span>"),
            std::string::npos);
}

TEST(HtmlReportGallery, FiltersArePureCssRadiosBeforeTheGalleryWithCounts) {
  const std::string html = FormatHtmlReport(FourShaders());
  const size_t gallery = html.find("<section id=\"gallery\">");
  for (const char* id : {"filter-all\" checked>", "filter-fail\">", "filter-warn\">"}) {
    const size_t input =
        html.find("<input type=\"radio\" class=\"filter\" name=\"filter\" id=\"" + std::string(id));
    ASSERT_NE(input, std::string::npos) << id;
    // `~` reaches only later siblings: the inputs must come before the sections.
    EXPECT_LT(input, gallery) << id;
  }
  EXPECT_NE(html.find("<label for=\"filter-all\">all (4)</label>"), std::string::npos);
  EXPECT_NE(html.find("<label for=\"filter-fail\">failing (1)</label>"), std::string::npos);
  EXPECT_NE(html.find("<label for=\"filter-warn\">warnings (1)</label>"), std::string::npos);
  EXPECT_NE(html.find("#filter-fail:checked~#gallery .tile:not(.is-fail)"), std::string::npos);
  EXPECT_NE(html.find("#filter-warn:checked~#shaders .shader:not(.is-warn)"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_NE(html.find("default-src 'none'"), std::string::npos);
}

TEST(HtmlReportGallery, EscapesFileNamesInTiles) {
  HtmlReport report;
  report.entries.push_back(
      Entry("dir/<script>alert(\"x\")</script>'.glsl", StepStatus::kFail, StepStatus::kPass, true));
  const std::string html = FormatHtmlReport(report);
  const std::string_view gallery = Between(html, "<section id=\"gallery\">", "</section>");
  ASSERT_FALSE(gallery.empty());
  EXPECT_EQ(gallery.find("<script"), std::string::npos);
  const std::string escaped = "dir/&lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt;&#39;.glsl";
  EXPECT_NE(gallery.find("title=\"" + escaped + "\""), std::string::npos);
  EXPECT_NE(gallery.find("alt=\"render of " + escaped + "\""), std::string::npos);
  EXPECT_NE(gallery.find("<span class=\"name\">" + escaped + "</span>"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
}

std::string Error(int line, std::string_view message) {
  return "a.glsl:" + std::to_string(line) + ":5: error: " + std::string(message) + "\n";
}

TEST(HtmlReportGallery, FoldsA25ErrorCascadeToItsFirstErrorAnd24More) {
  HtmlReport report;
  ReportEntry entry = Entry("a.glsl", StepStatus::kFail, StepStatus::kFail, false);
  for (int line = 1; line <= 25; ++line) {
    entry.check.findings.push_back({Error(line, "<cascade>"), "glslang 7"});
    // A finding of shaderport's own stands alone, even among the cascade.
    if (line == 10) entry.check.findings.push_back({Error(10, "OWN-RULE"), ""});
  }
  report.entries.push_back(entry);
  const std::string html = FormatHtmlReport(report);

  EXPECT_EQ(Occurrences(html, "<details class=\"cascade\">"), 1u);
  EXPECT_EQ(Occurrences(html, "+24 more errors from the same compile"), 1u);
  const std::string_view folded = Between(html, "<details class=\"cascade\">", "</details>");
  EXPECT_EQ(Occurrences(folded, "error: &lt;cascade&gt;"), 24u);
  EXPECT_EQ(folded.find("a.glsl:1:5:"), std::string::npos);
  EXPECT_NE(folded.find("a.glsl:25:5:"), std::string::npos);
  EXPECT_EQ(folded.find("OWN-RULE"), std::string::npos);
  // Outside the fold: the first error, shown before it, and the own finding.
  const size_t details = html.find("<details class=\"cascade\">");
  EXPECT_EQ(Occurrences(html, "error: &lt;cascade&gt;"), 25u);
  EXPECT_LT(html.find("a.glsl:1:5: error: &lt;cascade&gt;"), details);
  EXPECT_EQ(Occurrences(html, "OWN-RULE"), 1u);
  EXPECT_GT(html.find("OWN-RULE"), html.find("</details>"));
  EXPECT_EQ(html.find("<cascade>"), std::string::npos);
}

TEST(HtmlReportGallery, EachCascadeFoldsOnItsOwnAndALoneErrorIsNotFolded) {
  HtmlReport report;
  ReportEntry entry = Entry("a.glsl", StepStatus::kFail, StepStatus::kFail, false);
  entry.check.findings = {{Error(1, "ERR-A1"), "glslang 1"},
                          {Error(2, "ERR-B1"), "glslang 2"},
                          {Error(3, "ERR-A2"), "glslang 1"},
                          {Error(4, "ALONE"), "mesa 1"}};
  entry.render.findings = {{Error(5, "ERR-C1"), "glslang 1"}, {Error(6, "ERR-C2"), "glslang 1"}};
  report.entries.push_back(entry);
  const std::string html = FormatHtmlReport(report);
  // A2 folds under A1 and C2 under C1 (another step); B1 and ALONE have no followers.
  EXPECT_EQ(Occurrences(html, "<details class=\"cascade\">"), 2u);
  EXPECT_EQ(Occurrences(html, "+1 more error from the same compile"), 2u);
  EXPECT_LT(html.find("ERR-A1"), html.find("ERR-A2"));
  EXPECT_LT(html.find("ERR-A2"), html.find("ERR-B1"));  // folded right under its first error
  EXPECT_GT(html.find("ERR-C2"), html.find("ERR-C1"));
}

SourceRange In(FileId file) { return SourceRange{file, 0, 1}; }

TEST(HtmlReportGallery, CascadesAreCompilerErrorsPerFile) {
  const auto key = [](Severity severity, const char* rule, FileId file) {
    return CascadeOf(MakeDiagnostic(severity, rule, In(file), "m"));
  };
  EXPECT_EQ(key(Severity::kError, "glslang/undeclared-identifier", 3), "glslang 3");
  EXPECT_EQ(key(Severity::kError, "glslang/error", 3), "glslang 3");
  EXPECT_EQ(key(Severity::kError, "glslang/error", 4), "glslang 4");
  EXPECT_EQ(key(Severity::kError, "render/compile-error", 3), "mesa 3");
  EXPECT_EQ(key(Severity::kWarning, "glslang/warning", 3), "");
  EXPECT_EQ(key(Severity::kError, "webgl2/gl-fragcolor", 3), "");
  EXPECT_EQ(key(Severity::kError, "render/timeout", 3), "");
}

}  // namespace
}  // namespace shaderport::driver
