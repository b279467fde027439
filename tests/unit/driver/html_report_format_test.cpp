// The HTML page from report data alone: escaping, data URIs, counts.
#include <gtest/gtest.h>

#include <string>

#include "driver/html_report/html_report.h"
#include "driver/html_report/png_base64.h"
#include "render/png_io.h"

namespace shaderport::driver {
namespace {

TEST(HtmlReportFormat, Base64MatchesRfc4648Vectors) {
  EXPECT_EQ(Base64Encode(""), "");
  EXPECT_EQ(Base64Encode("f"), "Zg==");
  EXPECT_EQ(Base64Encode("fo"), "Zm8=");
  EXPECT_EQ(Base64Encode("foo"), "Zm9v");
  EXPECT_EQ(Base64Encode("foob"), "Zm9vYg==");
  EXPECT_EQ(Base64Encode("fooba"), "Zm9vYmE=");
  EXPECT_EQ(Base64Encode("foobar"), "Zm9vYmFy");
  EXPECT_EQ(Base64Encode(std::string("\xff\x00\xfe", 3)), "/wD+");
}

TEST(HtmlReportFormat, EscapesMarkupCharacters) {
  EXPECT_EQ(HtmlEscape("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
}

TEST(HtmlReportFormat, EncodesPngWithSignatureAndRejectsBadImages) {
  render::ImageRgba8 image;
  image.width = 2;
  image.height = 3;
  image.pixels.assign(2 * 3 * 4, 200);
  const std::string png = render::EncodePng(image);
  ASSERT_GE(png.size(), 24u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(png, render::EncodePng(image));  // deterministic
  image.pixels.pop_back();
  EXPECT_EQ(render::EncodePng(image), "");
}

TEST(HtmlReportFormat, PageEscapesEverythingUserControlledAndCounts) {
  HtmlReport report;
  report.tool_version = "9.9.9";
  ReportEntry broken;
  broken.path = "dir/<script>alert(1)</script>.glsl";
  broken.dialect = "shadertoy";
  broken.stage = "fragment";
  broken.check.status = StepStatus::kFail;
  broken.check.findings = {
      {"x.glsl:4:11: error: '>' wrong operand types\n    if (a > 0 && b < 1)\n", "glslang 1"}};
  broken.port.status = StepStatus::kPass;
  broken.render.status = StepStatus::kWarn;
  broken.png = "PNGDATA";
  ReportEntry skipped;
  skipped.path = "b.vert";
  report.entries = {broken, skipped};

  const std::string html = FormatHtmlReport(report);
  EXPECT_TRUE(html.starts_with("<!DOCTYPE html>"));
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  EXPECT_NE(html.find("&#39;&gt;&#39; wrong operand types"), std::string::npos);
  EXPECT_NE(html.find("if (a &gt; 0 &amp;&amp; b &lt; 1)"), std::string::npos);
  EXPECT_NE(html.find("src=\"data:image/png;base64," + Base64Encode("PNGDATA") + "\""),
            std::string::npos);
  // No external resources: nothing is fetched from anywhere.
  EXPECT_EQ(html.find("http:"), std::string::npos);
  EXPECT_EQ(html.find("https:"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  // And a policy that would block scripts and loads if something got through.
  EXPECT_NE(html.find("Content-Security-Policy\" content=\"default-src 'none';"),
            std::string::npos);

  const ReportCounts counts = CountReport(report);
  EXPECT_EQ(counts.shaders, 2u);
  EXPECT_EQ(counts.check.fail, 1u);
  EXPECT_EQ(counts.check.skipped, 1u);
  EXPECT_EQ(counts.render.warn, 1u);
  EXPECT_EQ(counts.thumbnails, 1u);
  EXPECT_EQ(html, FormatHtmlReport(report));
}

}  // namespace
}  // namespace shaderport::driver
