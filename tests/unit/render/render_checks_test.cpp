// Picture checks, Mesa log parsing, the loop-cap scan and the pipe format, on
// synthetic data (no rendering).
#include "render/render_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "render/loop_cap.h"
#include "render/mesa_log.h"
#include "render/outcome_wire.h"
#include "render/shader_text.h"

namespace shaderport::render {
namespace {

RenderOutcome Filled(float r, float g, float b, float a = 1.0f) {
  RenderOutcome outcome;
  outcome.status = RenderStatus::kOk;
  outcome.width = 4;
  outcome.height = 4;
  for (int i = 0; i < 16; ++i) outcome.pixels.insert(outcome.pixels.end(), {r, g, b, a});
  return outcome;
}

std::vector<std::string> Rules(const DiagnosticList& list) {
  std::vector<std::string> rules;
  for (const auto& d : list) rules.push_back(d.rule_id);
  return rules;
}

using Strings = std::vector<std::string>;

TEST(RenderChecks, VariedPictureIsClean) {
  RenderOutcome outcome = Filled(0.2f, 0.3f, 0.4f);
  outcome.pixels[0] = 0.9f;
  EXPECT_TRUE(CheckPixels(outcome, {}).empty());
}

TEST(RenderChecks, FlatColoursAreReportedOnce) {
  EXPECT_EQ(Rules(CheckPixels(Filled(0.2f, 0.3f, 0.4f), {})), Strings{"render/single-colour"});
  EXPECT_EQ(Rules(CheckPixels(Filled(0, 0, 0), {})), Strings{"render/all-black"});
  EXPECT_EQ(Rules(CheckPixels(Filled(1.5f, 2.0f, 1.0f), {})), Strings{"render/blown-out"});
  EXPECT_EQ(Rules(CheckPixels(Filled(0, 0, 0, 0), {})), Strings{"render/unwritten-pixels"});
}

// Browsers draw NaN in a GPU-dependent colour (a warning); infinities clamp the
// same everywhere in an 8-bit canvas (a note).
TEST(RenderChecks, NanIsAWarningWithAPositionAndInfinityANote) {
  RenderOutcome outcome = Filled(0.2f, 0.3f, 0.4f);
  outcome.pixels[1] = 0.5f;
  outcome.pixels[4 * 5 + 2] = std::numeric_limits<float>::quiet_NaN();  // x=1, y=1 from bottom
  outcome.pixels[4 * 6] = std::numeric_limits<float>::infinity();
  const DiagnosticList found = CheckPixels(outcome, {});
  ASSERT_EQ(Rules(found), Strings{"render/nan-or-inf"});
  EXPECT_EQ(found[0].severity, Severity::kWarning);
  EXPECT_NE(found[0].message.find("1 of 16 pixels are NaN"), std::string::npos) << found[0].message;
  EXPECT_NE(found[0].message.find("(1, 2)"), std::string::npos) << found[0].message;  // top-down
  outcome.pixels[4 * 5 + 2] = 0.5f;
  const DiagnosticList infinite = CheckPixels(outcome, {});
  ASSERT_EQ(Rules(infinite), Strings{"render/nan-or-inf"});
  EXPECT_EQ(infinite[0].severity, Severity::kNote);
}

TEST(RenderChecks, SentinelAndSiteInitialValueAreUnwritten) {
  RenderOutcome outcome = Filled(0.2f, 0.3f, 0.4f);
  outcome.pixels[1] = 0.6f;
  std::copy(kSentinel.begin(), kSentinel.end(), outcome.pixels.begin() + 8);
  for (int c = 0; c < 3; ++c) outcome.pixels[12 + c] = 1e20f;
  const DiagnosticList found = CheckPixels(outcome, {});
  EXPECT_EQ(Rules(found), (Strings{"render/unwritten-pixels", "render/unwritten-pixels"}));
}

TEST(RenderChecks, MeshRenderOnlyFailsWhenNothingIsDrawn) {
  CheckContext mesh;
  mesh.expect_full_coverage = false;
  RenderOutcome outcome = Filled(kSentinel[0], kSentinel[1], kSentinel[2], kSentinel[3]);
  EXPECT_EQ(Rules(CheckPixels(outcome, mesh)), Strings{"render/unwritten-pixels"});
  outcome.pixels[0] = 0.5f;
  outcome.pixels[1] = 0.5f;
  outcome.pixels[2] = 0.5f;
  outcome.pixels[3] = 1.0f;
  EXPECT_TRUE(CheckPixels(outcome, mesh).empty());
}

TEST(RenderChecks, FailedRendersBecomeOneDiagnostic) {
  RenderOutcome outcome;
  outcome.status = RenderStatus::kTimeout;
  outcome.message = "killed";
  EXPECT_EQ(Rules(CheckOutcome(outcome, {})), Strings{"render/timeout"});
  outcome.status = RenderStatus::kCrashed;
  EXPECT_EQ(Rules(CheckOutcome(outcome, {})), Strings{"render/crashed"});
  outcome.status = RenderStatus::kContextFailed;
  EXPECT_EQ(Rules(CheckOutcome(outcome, {})), Strings{"render/backend-unavailable"});
  outcome.status = RenderStatus::kLinkFailed;
  EXPECT_EQ(Rules(CheckOutcome(outcome, {})), Strings{"render/link-error"});
  RenderOutcome ok = Filled(0.1f, 0.2f, 0.3f);
  ok.pixels[0] = 0.7f;
  ok.gl_errors = {"GL_INVALID_OPERATION after glDrawArrays"};
  EXPECT_EQ(Rules(CheckOutcome(ok, {})), Strings{"render/gl-error"});
}

TEST(RenderChecks, GeneratedLinesStayAtTheAnchorAndSayWhere) {
  RenderOutcome outcome;
  outcome.status = RenderStatus::kCompileFailed;
  outcome.fragment_log = "0:3(10): error: `foo' undeclared\n0:9(1): error: bad\n";
  CheckContext context;
  context.anchor = {2, 0, 0};
  context.map_line = [](model::Stage, uint32_t line) -> std::optional<SourceRange> {
    if (line == 9) return SourceRange{2, 40, 45};
    return std::nullopt;
  };
  const DiagnosticList found = CheckOutcome(outcome, context);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].range, (SourceRange{2, 0, 0}));
  EXPECT_NE(found[0].message.find("line 3 of the generated text"), std::string::npos);
  EXPECT_EQ(found[1].range, (SourceRange{2, 40, 45}));
}

TEST(ShaderText, UnusedOutputsAreFound) {
  EXPECT_EQ(UnusedOutputs("out vec4 a;\nlayout(location = 1) out highp vec4 b;\n"
                          "out vec4 c[2];\nvoid main() { a = vec4(1); /* b */ }\n"),
            (Strings{"b", "c"}));
  EXPECT_TRUE(UnusedOutputs("out vec4 o;\nvoid main() { o = vec4(0); }").empty());
}

TEST(MesaLog, ParsesLocationsSeveritiesAndContinuations) {
  const auto entries = ParseMesaLog(
      "0:5(2): error: no matching function for call to `pow(float, int)'; candidates are:\n"
      "0:5(2): error:    float pow(float, float)\n"
      "0:7(1): warning: unused\n"
      "error: linking failed\n");
  ASSERT_EQ(entries.size(), 4u);
  EXPECT_EQ(entries[0].line, 5u);
  EXPECT_TRUE(entries[0].is_error);
  EXPECT_EQ(entries[0].message.substr(0, 11), "no matching");
  EXPECT_FALSE(entries[2].is_error);
  EXPECT_EQ(entries[3].line, 0u);
  EXPECT_EQ(entries[3].message, "linking failed");
}

TEST(LoopCap, NotesLoopsThatMayExceedLlvmpipesCap) {
  const SourceFile file(0, "loops.glsl",
                        "#define STEPS 300\n"
                        "void f() {\n"
                        "  for (int i = 0; i < 100; i++) {}\n"     // fine
                        "  for (int i = 0; i < 100000; i++) {}\n"  // over
                        "  for (int i = 0; i < STEPS; i++) {\n"    // nested 300 * 300
                        "    for (int j = 0; j < STEPS; j++) {}\n"
                        "  }\n"
                        "  for (;;) { break; }\n"                   // unbounded
                        "  while (x < n) {}\n"                      // unknown: silent
                        "  // for (int k = 0; k < 1000000; k++)\n"  // comment
                        "}\n");
  const DiagnosticList notes = LoopCapNotes(file);
  std::vector<uint32_t> lines;
  for (const auto& d : notes) {
    EXPECT_EQ(d.rule_id, "render/loop-cap");
    EXPECT_EQ(d.severity, Severity::kNote);
    lines.push_back(file.LocationOf(d.range.begin).line);
  }
  EXPECT_EQ(lines, (std::vector<uint32_t>{4, 6, 8}));
}

TEST(OutcomeWire, RoundTripsAndRejectsTruncation) {
  RenderOutcome outcome = Filled(0.25f, std::nanf(""), 1e20f);
  outcome.fragment_log = "0:1(1): error: x";
  outcome.gl_errors = {"GL_INVALID_ENUM after glClear"};
  const std::string bytes = EncodeOutcome(outcome);
  const auto decoded = DecodeOutcome(bytes);
  ASSERT_TRUE(decoded.has_value());
  EXPECT_EQ(decoded->fragment_log, outcome.fragment_log);
  EXPECT_EQ(decoded->gl_errors, outcome.gl_errors);
  ASSERT_EQ(decoded->pixels.size(), outcome.pixels.size());
  EXPECT_TRUE(std::isnan(decoded->pixels[1]));
  EXPECT_FALSE(DecodeOutcome(bytes.substr(0, bytes.size() - 1)).has_value());
  EXPECT_FALSE(DecodeOutcome("").has_value());
}

// A render that failed to compile sends no pixels: decoding must not hand
// memcpy the empty vector's null pointer (UBSan caught it).
TEST(OutcomeWire, RoundTripsAnOutcomeWithoutPixels) {
  RenderOutcome outcome;
  outcome.fragment_log = "0:5(2): error: undeclared";
  const auto decoded = DecodeOutcome(EncodeOutcome(outcome));
  ASSERT_TRUE(decoded.has_value());
  EXPECT_TRUE(decoded->pixels.empty());
  EXPECT_EQ(decoded->fragment_log, outcome.fragment_log);
}

TEST(ToImage, FlipsRowsAndRoundsLikeA8BitCanvas) {
  RenderOutcome outcome = Filled(0.0f, 0.5f, 2.0f);
  outcome.pixels[0] = 1.0f;  // bottom-left in GL
  const ImageRgba8 image = ToImage(outcome);
  EXPECT_EQ(image.pixels[(3 * 4 + 0) * 4], 255);  // bottom-left of the top-down image
  EXPECT_EQ(image.pixels[0], 0);
  EXPECT_EQ(image.pixels[1], 128);
  EXPECT_EQ(image.pixels[2], 255);
}

// Regression: discarded pixels showed the clear sentinel's garish colour in the PNG;
// a browser's canvas holds the transparent black it was cleared to.
TEST(ToImage, DiscardedPixelsAreTransparentBlack) {
  RenderOutcome outcome = Filled(0.2f, 0.4f, 0.6f);
  std::copy(kSentinel.begin(), kSentinel.end(), outcome.pixels.begin());  // bottom-left
  const ImageRgba8 image = ToImage(outcome);
  const size_t bottom_left = (3 * 4 + 0) * 4;
  for (size_t c = 0; c < 4; ++c) EXPECT_EQ(image.pixels[bottom_left + c], 0) << c;
  EXPECT_EQ(image.pixels[1], 102);  // an ordinary pixel is unchanged
}

}  // namespace
}  // namespace shaderport::render
