// `report --html` end to end on a small directory copied from the corpus: a ShaderToy
// pass, a WebGL2 shader, a ShaderToy pass with a typing error and one whose undeclared
// name gives glslang several errors.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "driver/html_report/build_report.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

std::optional<std::string> Base64Decode(std::string_view text) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  if (text.size() % 4 != 0) return std::nullopt;
  std::string out;
  for (size_t i = 0; i < text.size(); i += 4) {
    int v[4];
    int pad = 0;
    for (int k = 0; k < 4; ++k) {
      if (text[i + k] == '=' && i + 4 == text.size() && k >= 2) {
        v[k] = 0;
        ++pad;
      } else if ((v[k] = value(text[i + k])) < 0 || pad > 0) {
        return std::nullopt;
      }
    }
    const uint32_t n = (v[0] << 18) | (v[1] << 12) | (v[2] << 6) | v[3];
    out += static_cast<char>(n >> 16);
    if (pad < 2) out += static_cast<char>((n >> 8) & 255);
    if (pad < 1) out += static_cast<char>(n & 255);
  }
  return out;
}

std::string Text(const ReportStep& step) {
  std::string text;
  for (const ReportFinding& finding : step.findings) text += finding.text;
  return text;
}

uint32_t BigEndian(const std::string& bytes, size_t at) {
  return (uint32_t{static_cast<uint8_t>(bytes[at])} << 24) |
         (uint32_t{static_cast<uint8_t>(bytes[at + 1])} << 16) |
         (uint32_t{static_cast<uint8_t>(bytes[at + 2])} << 8) |
         uint32_t{static_cast<uint8_t>(bytes[at + 3])};
}

class HtmlReportPipeline : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // ctest runs each test in its own process, in parallel: one directory each.
    dir_ = new fs::path(fs::path(::testing::TempDir()) /
                        ("shaderport-html-report-" + std::to_string(::getpid())));
    fs::remove_all(*dir_);
    fs::create_directories(*dir_);
    const fs::path corpus = fs::path(SHADERPORT_SOURCE_DIR) / "corpus";
    fs::copy_file(corpus / "ao/template.glsl", *dir_ / "a-template.glsl");
    fs::copy_file(corpus / "strict-typing/compare-float-with-int.glsl", *dir_ / "b-broken.glsl");
    fs::copy_file(corpus / "strict-typing/control-explicit-conversions.frag",
                  *dir_ / "c-webgl2.frag");
    std::ofstream(*dir_ / "d-cascade.glsl") << "void mainImage(out vec4 o, in vec2 u) {\n"
                                               "  o = vec4(missing);\n"
                                               "  o.x = missing.x;\n"
                                               "  o.y = missing.y;\n"
                                               "}\n";
    HtmlReportOptions options;
    options.paths = {*dir_};
    options.render.hermetic = true;
    options.tool_version = "test";
    options.jobs = 1;
    run_ = new HtmlReportRun(BuildHtmlReport(options));
    html1_ = new std::string(FormatHtmlReport(run_->report));
    options.jobs = 2;
    html2_ = new std::string(FormatHtmlReport(BuildHtmlReport(options).report));
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
    delete run_;
    delete html1_;
    delete html2_;
  }
  static const ReportEntry& Entry(std::string_view name) {
    for (const ReportEntry& entry : run_->report.entries) {
      if (entry.path.ends_with(name)) return entry;
    }
    ADD_FAILURE() << "no entry " << name;
    return run_->report.entries.front();
  }

  static fs::path* dir_;
  static HtmlReportRun* run_;
  static std::string* html1_;
  static std::string* html2_;
};
fs::path* HtmlReportPipeline::dir_ = nullptr;
HtmlReportRun* HtmlReportPipeline::run_ = nullptr;
std::string* HtmlReportPipeline::html1_ = nullptr;
std::string* HtmlReportPipeline::html2_ = nullptr;

TEST_F(HtmlReportPipeline, EveryShaderHasAnEntryWithItsSteps) {
  ASSERT_EQ(run_->report.entries.size(), 4u);
  EXPECT_TRUE(run_->usage_errors.empty());
  const ReportEntry& good = Entry("a-template.glsl");
  EXPECT_EQ(good.dialect, "shadertoy");
  EXPECT_EQ(good.check.status, StepStatus::kPass);
  EXPECT_EQ(good.port.status, StepStatus::kPass);
  EXPECT_NE(good.render.status, StepStatus::kFail) << Text(good.render);
  EXPECT_FALSE(good.png.empty());

  const ReportEntry& broken = Entry("b-broken.glsl");
  EXPECT_EQ(broken.check.status, StepStatus::kFail);
  ASSERT_FALSE(broken.check.findings.empty());
  EXPECT_NE(broken.check.findings.front().text.find("error:"), std::string::npos);
  // glslang's error is keyed for folding; the text is one finding, no summary line.
  EXPECT_TRUE(broken.check.findings.front().cascade.starts_with("glslang "));
  EXPECT_EQ(broken.check.findings.front().text.find(" checked)"), std::string::npos);
  // `port` fixes the int literal, so the port validates and renders.
  EXPECT_EQ(broken.port.status, StepStatus::kPass) << Text(broken.port);
  EXPECT_FALSE(broken.png.empty());

  const ReportEntry& webgl2 = Entry("c-webgl2.frag");
  EXPECT_EQ(webgl2.dialect, "webgl2");
  EXPECT_EQ(webgl2.check.status, StepStatus::kPass);
  EXPECT_FALSE(webgl2.png.empty()) << Text(webgl2.render);
}

TEST_F(HtmlReportPipeline, PageHasSectionsBadgesAndEscapedDiagnostics) {
  const std::string& html = *html1_;
  EXPECT_NE(html.find("<section id=\"summary\">"), std::string::npos);
  // The gallery opens the page: one tile per shader, the broken one marked failing.
  const size_t gallery = html.find("<section id=\"gallery\">");
  ASSERT_NE(gallery, std::string::npos);
  EXPECT_LT(gallery, html.find("<section id=\"summary\">"));
  EXPECT_LT(gallery, html.find("<pre>"));
  size_t tiles = 0;
  for (size_t at = html.find("<a class=\"tile "); at != std::string::npos;
       at = html.find("<a class=\"tile ", at + 1)) {
    ++tiles;
  }
  EXPECT_EQ(tiles, 4u);
  EXPECT_NE(html.find("<a class=\"tile is-fail\" href=\"#shader-2\""), std::string::npos);
  EXPECT_NE(html.find("<section id=\"shaders\">"), std::string::npos);
  EXPECT_NE(html.find("<tr><th>check</th><td>2</td><td>0</td><td>2</td><td>0</td></tr>"),
            std::string::npos);
  for (const char* name : {"a-template.glsl", "b-broken.glsl", "c-webgl2.frag", "d-cascade.glsl"}) {
    EXPECT_NE(html.find(name), std::string::npos) << name;
  }
  EXPECT_NE(html.find("class=\"badge fail\">check: fail"), std::string::npos);
  // The echoed source line `if (uv.x > 0)` appears escaped, never raw.
  EXPECT_NE(html.find("if (uv.x &gt; 0)"), std::string::npos);
  EXPECT_EQ(html.find("if (uv.x > 0)"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
}

TEST_F(HtmlReportPipeline, GlslangCascadeIsFoldedUnderItsFirstError) {
  const ReportEntry& cascade = Entry("d-cascade.glsl");
  const std::vector<ReportFinding>& findings = cascade.check.findings;
  ASSERT_GE(findings.size(), 2u) << Text(cascade.check);
  for (const ReportFinding& finding : findings) {
    EXPECT_EQ(finding.cascade, findings.front().cascade) << finding.text;
  }
  EXPECT_NE(findings.front().text.find("'missing': undeclared identifier"), std::string::npos);
  const std::string& html = *html1_;
  const size_t details = html.find("id=\"shader-4\"");
  ASSERT_NE(details, std::string::npos);
  const std::string more = "+" + std::to_string(findings.size() - 1) + " more errors";
  EXPECT_NE(html.find("<details class=\"cascade\"><summary>" + more, details), std::string::npos);
}

TEST_F(HtmlReportPipeline, EveryRenderedShaderHasAValidPngDataUri) {
  const std::string& html = *html1_;
  const std::string prefix = "src=\"data:image/png;base64,";
  size_t found = 0;
  for (size_t at = html.find(prefix); at != std::string::npos; at = html.find(prefix, at + 1)) {
    const size_t begin = at + prefix.size();
    const size_t end = html.find('"', begin);
    ASSERT_NE(end, std::string::npos);
    const std::optional<std::string> png = Base64Decode(html.substr(begin, end - begin));
    ASSERT_TRUE(png.has_value());
    ASSERT_GE(png->size(), 33u);
    EXPECT_EQ(png->substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    EXPECT_EQ(png->substr(12, 4), "IHDR");
    EXPECT_EQ(BigEndian(*png, 16), 128u);
    EXPECT_EQ(BigEndian(*png, 20), 128u);
    EXPECT_EQ(png->substr(png->size() - 8, 4), "IEND");
    ++found;
  }
  EXPECT_EQ(found, 3u);
  EXPECT_EQ(found, CountReport(run_->report).thumbnails);
}

TEST_F(HtmlReportPipeline, SameBytesWithOneOrTwoJobs) { EXPECT_EQ(*html1_, *html2_); }

}  // namespace
}  // namespace shaderport::driver
