// Fingerprints: what keeps a finding's identity across edits, and what does not.
#include "report/fingerprint.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

namespace shaderport {
namespace {

// One file named `name` (under `base`) with one finding of `rule` at the first
// `needle` in `text`; returns that finding's fingerprint.
std::string FingerprintOf(std::string text, std::string_view needle, std::string rule = "x/y",
                          std::string name = "/repo/shaders/a.frag", std::string base = "/repo") {
  SourceManager sources;
  const SourceFile& file = sources.Add(std::move(name), text);
  CheckReport report;
  report.sources = &sources;
  const auto at = static_cast<uint32_t>(text.find(needle));
  EXPECT_NE(text.find(needle), std::string::npos) << needle;
  Diagnostic diagnostic =
      MakeDiagnostic(Severity::kWarning, std::move(rule),
                     {file.Id(), at, at + static_cast<uint32_t>(needle.size())}, "message");
  report.files.push_back({&file, "webgl2", "fragment", {diagnostic}});
  return FingerprintReport(report, base).at(0).at(0).fingerprint;
}

const char* const kShader =
    "precision mediump float;\n"
    "uniform float t;\n"
    "void main() {\n"
    "  float x = t * 2;\n"
    "  gl_FragColor = vec4(x);\n"
    "}\n";

// A renamed rule (diag/rule_renames.def) keeps the fingerprint its old id gave, so a
// baseline or a SARIF alert written before the rename still matches its findings.
TEST(Fingerprint, RenamedRuleKeepsItsFirstIdsFingerprint) {
  EXPECT_EQ(FingerprintOf(kShader, "2", "port/version"),
            FingerprintOf(kShader, "2", "webgl2/version"));
  EXPECT_NE(FingerprintOf(kShader, "2", "port/version"), FingerprintOf(kShader, "2", "x/y"));
}

TEST(Fingerprint, NormalizeWhitespaceCollapsesAndTrims) {
  EXPECT_EQ(NormalizeWhitespace("  \tfloat   x =\t1;  \r"), "float x = 1;");
  EXPECT_EQ(NormalizeWhitespace(" \t "), "");
  EXPECT_EQ(NormalizeWhitespace(""), "");
}

TEST(Fingerprint, FormatIsHashAndOccurrence) {
  const std::string fingerprint = FingerprintOf(kShader, "2");
  ASSERT_EQ(fingerprint.size(), 18u) << fingerprint;
  EXPECT_EQ(fingerprint.substr(16), ":1");
  EXPECT_EQ(fingerprint.find_first_not_of("0123456789abcdef"), 16u);
}

TEST(Fingerprint, SurvivesLinesAddedAboveAndBlankLinesAround) {
  const std::string before = FingerprintOf(kShader, "2");
  std::string moved = std::string("// a comment\n\n#define K 1\n") + kShader;
  EXPECT_EQ(FingerprintOf(moved, "2"), before);
  // Blank lines between the finding and its neighbours do not count.
  std::string spaced = kShader;
  spaced.insert(spaced.find("  float x"), "\n\n");
  spaced.insert(spaced.find("  gl_FragColor"), "   \n");
  EXPECT_EQ(FingerprintOf(spaced, "2"), before);
}

TEST(Fingerprint, SurvivesReindentingAndMovingTheCheckout) {
  const std::string before = FingerprintOf(kShader, "2");
  std::string reindented = kShader;
  reindented.replace(reindented.find("  float x = t * 2;"), 18, "\t\tfloat  x = t *  2;   ");
  EXPECT_EQ(FingerprintOf(reindented, "2"), before);
  EXPECT_EQ(FingerprintOf(kShader, "2", "x/y", "/elsewhere/checkout/shaders/a.frag",
                          "/elsewhere/checkout"),
            before);
  EXPECT_EQ(FingerprintOf(kShader, "2", "x/y", "shaders/a.frag", ""), before);
}

TEST(Fingerprint, ChangesWithRuleFileLineTextNeighboursAndColumn) {
  const std::string before = FingerprintOf(kShader, "2");
  EXPECT_NE(FingerprintOf(kShader, "2", "x/z"), before);
  EXPECT_NE(FingerprintOf(kShader, "2", "x/y", "/repo/shaders/b.frag"), before);
  std::string edited_line = kShader;
  edited_line.replace(edited_line.find("t * 2"), 5, "t * 2 + 1");
  EXPECT_NE(FingerprintOf(edited_line, "2"), before);
  std::string edited_neighbour = kShader;
  edited_neighbour.replace(edited_neighbour.find("vec4(x)"), 7, "vec4(x, 1)");
  EXPECT_NE(FingerprintOf(edited_neighbour, "2"), before);
  EXPECT_NE(FingerprintOf(kShader, "t * 2"), FingerprintOf(kShader, "2"));
}

TEST(Fingerprint, RepeatsAreNumberedInReportOrder) {
  // The same statement twice, with the same neighbours: only the occurrence differs.
  const std::string text = "x;\ny = 1;\nx;\ny = 1;\nx;\n";
  SourceManager sources;
  const SourceFile& file = sources.Add("a.frag", text);
  CheckReport report;
  report.sources = &sources;
  FileReport file_report{&file, "webgl2", "fragment", {}};
  for (size_t at = text.find('1'); at != std::string::npos; at = text.find('1', at + 1)) {
    const auto begin = static_cast<uint32_t>(at);  // "1" on lines 2 and 4
    file_report.diagnostics.push_back(
        MakeDiagnostic(Severity::kWarning, "x/y", {file.Id(), begin, begin + 1}, "m"));
  }
  report.files.push_back(file_report);
  const auto fingerprints = FingerprintReport(report, "");
  ASSERT_EQ(fingerprints.at(0).size(), 2u);
  EXPECT_EQ(fingerprints[0][0].fingerprint.substr(0, 16),
            fingerprints[0][1].fingerprint.substr(0, 16));
  EXPECT_EQ(fingerprints[0][0].fingerprint.substr(16), ":1");
  EXPECT_EQ(fingerprints[0][1].fingerprint.substr(16), ":2");
}

TEST(Fingerprint, WholeFileFindingsAndSyntheticFilesUseTheCheckedFile) {
  SourceManager sources;
  const SourceFile& file = sources.Add("a.frag", "x;\n");
  const SourceFile& generated = sources.Add("<harness>", "uniform float t;\n", true);
  CheckReport report;
  report.sources = &sources;
  report.files.push_back({&file,
                          "webgl2",
                          "fragment",
                          {MakeDiagnostic(Severity::kError, "x/y", {}, "m"),
                           MakeDiagnostic(Severity::kError, "x/y", {generated.Id(), 0, 7}, "m")}});
  const auto fingerprints = FingerprintReport(report, "");
  EXPECT_EQ(FingerprintKey(&sources, &file, report.files[0].diagnostics[1], ""), "x/y\na.frag\n");
  EXPECT_EQ(fingerprints[0][1].fingerprint.substr(16), ":2");  // same key as the whole-file finding
}

}  // namespace
}  // namespace shaderport
