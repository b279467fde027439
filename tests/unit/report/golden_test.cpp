// Every output format on the sample report, compared with tests/golden/report/.
// SHADERPORT_UPDATE_GOLDENS=1 rewrites the files instead of comparing.
#include "golden.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "report/output_format.h"
#include "report_sample.h"

namespace shaderport {
namespace {

std::string GoldenPath(const std::string& name) {
  return std::string(SHADERPORT_SOURCE_DIR) + "/tests/golden/report/" + name;
}

void ExpectGolden(const std::string& name, const std::string& actual) {
  EXPECT_TRUE(shaderport::testing::MatchesGolden(actual, GoldenPath(name)));
}

TEST(ReportGolden, Text) {
  testing::ReportSample sample;
  ExpectGolden("sample.txt", FormatReport(sample.report, OutputFormat::kText, sample.options));
}

TEST(ReportGolden, TextInColour) {
  testing::ReportSample sample;
  sample.options.color = true;
  ExpectGolden("sample.color.txt",
               FormatReport(sample.report, OutputFormat::kText, sample.options));
}

TEST(ReportGolden, Json) {
  testing::ReportSample sample;
  ExpectGolden("sample.json", FormatReport(sample.report, OutputFormat::kJson, sample.options));
}

TEST(ReportGolden, Sarif) {
  testing::ReportSample sample;
  ExpectGolden("sample.sarif", FormatReport(sample.report, OutputFormat::kSarif, sample.options));
}

TEST(ReportGolden, Github) {
  testing::ReportSample sample;
  ExpectGolden("sample.github.txt",
               FormatReport(sample.report, OutputFormat::kGithub, sample.options));
}

TEST(ReportGolden, OutputIsDeterministic) {
  testing::ReportSample first;
  testing::ReportSample second;
  for (OutputFormat format :
       {OutputFormat::kText, OutputFormat::kJson, OutputFormat::kSarif, OutputFormat::kGithub}) {
    EXPECT_EQ(FormatReport(first.report, format, first.options),
              FormatReport(second.report, format, second.options));
  }
}

}  // namespace
}  // namespace shaderport
