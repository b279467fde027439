// The repository's corpus shaders that compile render cleanly and match their
// golden pictures; the real CLI (ShaderToy composition from src/validate) agrees.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "golden_image.h"
#include "render/isolated_render.h"
#include "render/render_checks.h"
#include "render_test_support.h"

namespace shaderport::render {
namespace {

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

struct CorpusCase {
  const char* path;  // under corpus/
  const char* golden;
  bool shadertoy;
};

const CorpusCase kCases[] = {
    {"ao/template.glsl", "ao-template", true},
    {"ao/variant-classic-step3.glsl", "ao-variant-classic-step3", true},
    {"ao/variant-multiplicative.glsl", "ao-variant-multiplicative", true},
    {"ao/variant-multiscale.glsl", "ao-variant-multiscale", true},
    {"ao/variant-jittered.glsl", "ao-variant-jittered", true},
    {"ao/variant-hemisphere.glsl", "ao-variant-hemisphere", true},
    {"ao/variant-fibonacci.glsl", "ao-variant-fibonacci", true},
    {"strict-typing/control-explicit-conversions.glsl", "control-explicit-conversions-glsl", true},
    {"strict-typing/control-explicit-conversions.frag", "control-explicit-conversions-frag", false},
};

class CorpusRender : public ::testing::TestWithParam<CorpusCase> {};

TEST_P(CorpusRender, RendersPassesChecksAndMatchesGolden) {
  const CorpusCase& c = GetParam();
  const std::string text = ReadText(std::string(SHADERPORT_SOURCE_DIR) + "/corpus/" + c.path);
  ASSERT_FALSE(text.empty()) << c.path;
  const RenderRequest request =
      testing::FragmentRequest(c.shadertoy ? testing::ShaderToyText(text) : text);
  const RenderOutcome outcome = RenderIsolated(request, testing::FastOptions());
  ASSERT_EQ(outcome.status, RenderStatus::kOk) << outcome.message << outcome.fragment_log;
  const DiagnosticList found = CheckOutcome(outcome, {});
  for (const Diagnostic& d : found) ADD_FAILURE() << d.rule_id << ": " << d.message;
  testing::ExpectMatchesGolden(ToImage(outcome), c.golden);
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusRender, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<CorpusCase>& param_info) {
                           std::string name = param_info.param.golden;
                           for (char& ch : name) {
                             if (ch == '-') ch = '_';
                           }
                           return name;
                         });

TEST(CorpusRender, CliRenderMatchesTheGolden) {
  // The CLI composes with the site's real header and epilogue (src/validate). The
  // goldens come from the library, which draws the text as given: --native keeps the
  // CLI's browser transforms (math as Chromium computes it) out of the comparison.
  if (!std::filesystem::exists(SHADERPORT_BINARY)) GTEST_SKIP() << "shaderport not built";
  if (testing::UpdatingGoldens()) GTEST_SKIP() << "goldens come from the library path";
  const std::string out = ::testing::TempDir() + "/render-cli-ao.png";
  const std::string command = std::string(SHADERPORT_BINARY) + " render --native --hermetic " +
                              SHADERPORT_SOURCE_DIR + "/corpus/ao/template.glsl -o " + out +
                              " > /dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  ImageRgba8 image;
  std::string error;
  ASSERT_TRUE(ReadPng(out, image, error)) << error;
  ImageRgba8 golden;
  ASSERT_TRUE(ReadPng(testing::GoldenPath("ao-template"), golden, error)) << error;
  EXPECT_TRUE(testing::MatchesWithinTolerance(image, golden));
}

}  // namespace
}  // namespace shaderport::render
