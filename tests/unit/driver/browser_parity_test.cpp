// `render` draws what Chromium draws: every shader of tests/render-parity/shaders is
// rendered (64x64, hermetic) and compared with the picture headless Chromium made of
// it (tests/render-parity/chromium, regenerated as its README says). Tolerance: no
// 8x8 block's mean R, G or B differs by more than 12/255. expected-findings.txt
// names the finding a shader must report, and whether it still has to match.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "driver/render_check/render_file.h"
#include "render/png_io.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = fs::path(SHADERPORT_SOURCE_DIR) / "tests" / "render-parity";
constexpr int kBlock = 8;
constexpr double kTolerance = 12.0;

// The largest difference of an 8x8 block's mean R, G or B, in 1/255 steps.
double WorstBlockDifference(const render::ImageRgba8& a, const render::ImageRgba8& b) {
  double worst = 0;
  for (uint32_t by = 0; by < a.height; by += kBlock) {
    for (uint32_t bx = 0; bx < a.width; bx += kBlock) {
      for (size_t c = 0; c < 3; ++c) {
        double sum = 0;
        int n = 0;
        for (uint32_t y = by; y < std::min(by + kBlock, a.height); ++y) {
          for (uint32_t x = bx; x < std::min(bx + kBlock, a.width); ++x) {
            const size_t at = (size_t{y} * a.width + x) * 4 + c;
            sum += int{a.pixels[at]} - int{b.pixels[at]};
            ++n;
          }
        }
        worst = std::max(worst, std::abs(sum / n));
      }
    }
  }
  return worst;
}

struct ExpectedFinding {
  bool matches = true;
  std::string rule;
};

std::map<std::string, ExpectedFinding> ExpectedFindings() {
  std::map<std::string, ExpectedFinding> expected;
  std::ifstream in(kDir / "expected-findings.txt");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string name, picture, rule;
    if (fields >> name >> picture >> rule) expected[name] = {picture == "matches", rule};
  }
  return expected;
}

RenderFileResult Render(const fs::path& shader, bool webgl_semantics, SourceManager& sources,
                        const SourceFile* common = nullptr, bool browser_optimiser = false) {
  RenderFileOptions options;
  options.browser_optimiser = browser_optimiser;
  options.common = common;
  options.base.width = 64;
  options.base.height = 64;
  options.render.hermetic = true;
  options.webgl_semantics = webgl_semantics;
  return RenderFile(shader, sources, options);
}

TEST(BrowserParity, RenderMatchesChromiumOrSaysWhyNot) {
  const auto expected = ExpectedFindings();
  int shaders = 0, differ_natively = 0;
  for (const auto& entry : fs::directory_iterator(kDir / "shaders")) {
    const std::string name = entry.path().stem().string();
    SCOPED_TRACE(name);
    ++shaders;
    render::ImageRgba8 reference;
    std::string error;
    ASSERT_TRUE(render::ReadPng((kDir / "chromium" / (name + ".png")).string(), reference, error))
        << error;
    SourceManager sources;
    const RenderFileResult result = Render(entry.path(), true, sources);
    ASSERT_TRUE(result.image.has_value());
    ASSERT_EQ(result.image->width, reference.width);
    ASSERT_EQ(result.image->height, reference.height);
    const double difference = WorstBlockDifference(*result.image, reference);
    const auto found = expected.find(name);
    if (found == expected.end() || found->second.matches) {
      EXPECT_LE(difference, kTolerance);
    }
    if (found != expected.end()) {
      EXPECT_TRUE(std::any_of(result.diagnostics.begin(), result.diagnostics.end(),
                              [&](const Diagnostic& d) { return d.rule_id == found->second.rule; }))
          << "expected " << found->second.rule;
    }
    SourceManager native_sources;
    const RenderFileResult native = Render(entry.path(), false, native_sources);
    if (native.image && WorstBlockDifference(*native.image, reference) > kTolerance) {
      ++differ_natively;
    }
  }
  EXPECT_GE(shaders, 10);
  // The set exercises real differences: without the browser's semantics most differ.
  EXPECT_GE(differ_natively, shaders / 2);
}

// Probes whose bits only the browser's optimiser (--browser-optimiser) gives, with why.
std::map<std::string, std::string> NeedTheOptimiser() {
  std::map<std::string, std::string> names;
  std::ifstream in(kDir / "math-needs-optimiser.txt");
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const size_t space = line.find(' ');
    names[line.substr(0, space)] = space == std::string::npos ? "" : line.substr(space + 1);
  }
  return names;
}

size_t DifferentBytes(const render::ImageRgba8& image, const render::ImageRgba8& reference) {
  size_t different = 0;
  for (size_t i = 0; i < reference.pixels.size(); ++i) {
    different += image.pixels[i] != reference.pixels[i] ? 1 : 0;
  }
  return different;
}

// tests/render-parity/math: each probe draws the bits of one built-in (or a
// division, a conversion) for 2,048 arguments; render must give Chromium's bits
// exactly, where llvmpipe's own math gives other bits; with the browser's optimiser
// every probe, without it every probe but those math-needs-optimiser.txt lists (which
// must then differ, or the list is stale).
TEST(BrowserParity, MathHasChromiumsBits) {
  const auto need_optimiser = NeedTheOptimiser();
  int probes = 0, differ_natively = 0;
  std::ifstream common_in(kDir / "math-common.glsl");
  std::stringstream common_text;
  common_text << common_in.rdbuf();
  ASSERT_FALSE(common_text.str().empty());
  for (const auto& entry : fs::directory_iterator(kDir / "math")) {
    const std::string name = entry.path().stem().string();
    SCOPED_TRACE(name);
    ++probes;
    render::ImageRgba8 reference;
    std::string error;
    ASSERT_TRUE(
        render::ReadPng((kDir / "math-chromium" / (name + ".png")).string(), reference, error))
        << error;
    // ShaderToy probes share math-common.glsl as their Common tab.
    const bool shadertoy = entry.path().extension() == ".glsl";
    SourceManager sources;
    const SourceFile& common = sources.Add("math-common.glsl", common_text.str());
    const RenderFileResult result =
        Render(entry.path(), true, sources, shadertoy ? &common : nullptr);
    ASSERT_TRUE(result.image.has_value());
    ASSERT_EQ(result.image->pixels.size(), reference.pixels.size());
    if (need_optimiser.contains(name)) {
      EXPECT_NE(DifferentBytes(*result.image, reference), 0U) << "listed as needing the optimiser";
    } else {
      EXPECT_EQ(DifferentBytes(*result.image, reference), 0U)
          << "bytes that differ from Chromium's";
    }
    const RenderFileResult optimised =
        Render(entry.path(), true, sources, shadertoy ? &common : nullptr, true);
    ASSERT_TRUE(optimised.image.has_value());
    EXPECT_EQ(DifferentBytes(*optimised.image, reference), 0U)
        << "bytes that differ from Chromium's with the browser's optimiser";
    SourceManager native_sources;
    const SourceFile& native_common = native_sources.Add("math-common.glsl", common_text.str());
    const RenderFileResult native =
        Render(entry.path(), false, native_sources, shadertoy ? &native_common : nullptr);
    if (native.image && native.image->pixels != reference.pixels) ++differ_natively;
  }
  EXPECT_GE(probes, 12);
  EXPECT_GE(differ_natively, probes - 1);  // each probe shows a real difference
}

// `buffer` is a word ES 3.10 reserves, so the text cannot go through the browser's
// optimiser (glslang compiles it as 310 es): render --browser-optimiser draws the browser
// semantics' text.
TEST(BrowserParity, PassTheOptimiserCannotTakeIsStillDrawn) {
  const fs::path path = fs::path(::testing::TempDir()) / "reserved-in-310.glsl";
  std::ofstream(path) << "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                         "  float buffer = fragCoord.x / iResolution.x;\n"
                         "  fragColor = vec4(buffer, 0.5, 0.25, 1.0);\n}\n";
  SourceManager sources;
  const RenderFileResult result = Render(path, true, sources, nullptr, true);
  ASSERT_TRUE(result.image.has_value());
  EXPECT_FALSE(HasErrors(result.diagnostics));
  const auto& pixels = result.image->pixels;
  EXPECT_EQ(pixels[0], 2);  // x = 0.5 / 64 in the top-left pixel
  EXPECT_EQ(pixels[1], 128);
  EXPECT_EQ(pixels[(64 * 63 + 63) * 4], 253);
}

}  // namespace
}  // namespace shaderport::driver
