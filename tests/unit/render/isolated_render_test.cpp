#include "render/isolated_render.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cstring>

#include "render/render_checks.h"
#include "render_test_support.h"

namespace shaderport::render {
namespace {

using testing::FastOptions;
using testing::FragmentRequest;
using testing::kGradient;
using testing::ShaderToyText;

bool HasRule(const DiagnosticList& list, const std::string& rule) {
  for (const auto& d : list) {
    if (d.rule_id == rule) return true;
  }
  return false;
}

TEST(IsolatedRender, GradientRendersAndPassesChecks) {
  const RenderOutcome outcome =
      RenderIsolated(FragmentRequest(ShaderToyText(kGradient)), FastOptions());
  ASSERT_EQ(outcome.status, RenderStatus::kOk) << outcome.message << outcome.fragment_log;
  ASSERT_EQ(outcome.pixels.size(), 64u * 64u * 4u);
  // Bottom-left pixel centre (0.5, 0.5) / 64; top-right is near (1, 1).
  EXPECT_NEAR(outcome.pixels[0], 0.5f / 64.0f, 1e-5f);
  EXPECT_NEAR(outcome.pixels[(64 * 64 - 1) * 4 + 1], 63.5f / 64.0f, 1e-5f);
  EXPECT_TRUE(outcome.gl_errors.empty());
  EXPECT_TRUE(CheckOutcome(outcome, {}).empty());
}

TEST(IsolatedRender, RendersAreBitIdenticalRunToRun) {
  const RenderRequest request = FragmentRequest(ShaderToyText(kGradient));
  const RenderOutcome a = RenderIsolated(request, FastOptions());
  const RenderOutcome b = RenderIsolated(request, FastOptions());
  ASSERT_EQ(a.status, RenderStatus::kOk);
  ASSERT_EQ(b.status, RenderStatus::kOk);
  EXPECT_EQ(0, std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)));
}

TEST(IsolatedRender, NanPixelsAreCaught) {
  const RenderOutcome outcome =
      RenderIsolated(FragmentRequest(ShaderToyText("void mainImage(out vec4 c, in vec2 p) {\n"
                                                   "  float z = p.x - p.x;\n"
                                                   "  c = vec4(vec3(z / z), 1.0);\n}\n")),
                     FastOptions());
  ASSERT_EQ(outcome.status, RenderStatus::kOk);
  EXPECT_TRUE(HasRule(CheckOutcome(outcome, {}), "render/nan-or-inf"));
}

TEST(IsolatedRender, NeverWrittenOutputIsCaught) {
  // A WebGL2 shader that never assigns its output. llvmpipe leaves it undefined
  // (zero or register leftovers), so the text tells, not the picture.
  const std::string text =
      "#version 300 es\nprecision highp float;\nout vec4 color; // the output\n"
      "uniform float iTime;\nvoid main() { float t = iTime; }\n";
  const RenderOutcome outcome = RenderIsolated(FragmentRequest(text), FastOptions());
  ASSERT_EQ(outcome.status, RenderStatus::kOk);
  CheckContext context;
  context.fragment_text = text;
  const DiagnosticList found = CheckOutcome(outcome, context);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].rule_id, "render/unwritten-pixels");
  EXPECT_NE(found[0].message.find("'color'"), std::string::npos);
}

TEST(IsolatedRender, NeverWrittenShaderToyOutputIsCaught) {
  // mainImage forgets fragColor: on Mesa the out parameter reads as zero (on the
  // site it may keep the 1e20 initial value, which the checks also catch).
  const RenderOutcome outcome =
      RenderIsolated(FragmentRequest(ShaderToyText("void mainImage(out vec4 c, in vec2 p) {\n"
                                                   "  vec2 uv = p / iResolution.xy;\n}\n")),
                     FastOptions());
  ASSERT_EQ(outcome.status, RenderStatus::kOk);
  const DiagnosticList found = CheckOutcome(outcome, {});
  ASSERT_TRUE(HasRule(found, "render/all-black"));
  EXPECT_NE(found[0].message.find("fragColor"), std::string::npos);
}

TEST(IsolatedRender, DiscardedPixelsKeepTheSentinel) {
  const RenderOutcome outcome = RenderIsolated(
      FragmentRequest(ShaderToyText("void mainImage(out vec4 c, in vec2 p) {\n"
                                    "  if (p.x < 10.0) discard;\n"
                                    "  c = vec4(p / iResolution.xy, 0.0, 1.0);\n}\n")),
      FastOptions());
  ASSERT_EQ(outcome.status, RenderStatus::kOk);
  const DiagnosticList found = CheckOutcome(outcome, {});
  ASSERT_TRUE(HasRule(found, "render/unwritten-pixels"));
  EXPECT_NE(found[0].message.find("640 of 4096"), std::string::npos) << found[0].message;
}

TEST(IsolatedRender, ConstantColourIsCaught) {
  const RenderOutcome outcome =
      RenderIsolated(FragmentRequest(ShaderToyText("void mainImage(out vec4 c, in vec2 p) {\n"
                                                   "  c = vec4(0.2, 0.4, 0.6, 1.0);\n}\n")),
                     FastOptions());
  ASSERT_EQ(outcome.status, RenderStatus::kOk);
  EXPECT_TRUE(HasRule(CheckOutcome(outcome, {}), "render/single-colour"));
}

TEST(IsolatedRender, EndlessLoopIsKilledWithinTheTimeout) {
  // llvmpipe caps loops at 65535 iterations, so the loop body must be expensive
  // enough that even the capped loop takes far longer than the timeout.
  const std::string heavy =
      "#define S(x) x = sin(x) * cos(x * 1.1) + 0.1;\n"
      "#define S8(x) S(x) S(x) S(x) S(x) S(x) S(x) S(x) S(x)\n"
      "void mainImage(out vec4 c, in vec2 p) {\n"
      "  float x = p.x;\n"
      "  for (;;) { S8(x) S8(x) S8(x) S8(x) S8(x) S8(x) S8(x) S8(x) if (x > 1e9) break; }\n"
      "  c = vec4(x);\n}\n";
  RenderOptions options = FastOptions();
  options.timeout = std::chrono::milliseconds(1500);
  const auto start = std::chrono::steady_clock::now();
  const RenderOutcome outcome = RenderIsolated(FragmentRequest(ShaderToyText(heavy)), options);
  const auto elapsed = std::chrono::steady_clock::now() - start;
  ASSERT_EQ(outcome.status, RenderStatus::kTimeout);
  EXPECT_LT(elapsed, std::chrono::milliseconds(3000));
  EXPECT_TRUE(HasRule(CheckOutcome(outcome, {}), "render/timeout"));
  // No child left behind: every child of this process has been reaped.
  EXPECT_EQ(waitpid(-1, nullptr, WNOHANG), -1);
}

TEST(IsolatedRender, CompileErrorsAreMappedThroughTheCallersLineMap) {
  const std::string text = ShaderToyText(
      "void mainImage(out vec4 c, in vec2 p) {\n  vec3 v = 1.0;\n  c = vec4(v, 1.0);\n}\n");
  const RenderOutcome outcome = RenderIsolated(FragmentRequest(text), FastOptions());
  ASSERT_EQ(outcome.status, RenderStatus::kCompileFailed);
  CheckContext context;
  context.anchor = {7, 0, 1};
  uint32_t mapped_line = 0;
  context.map_line = [&](model::Stage stage, uint32_t line) -> std::optional<SourceRange> {
    EXPECT_EQ(stage, model::Stage::kFragment);
    mapped_line = line;
    return SourceRange{7, line, line};
  };
  const DiagnosticList found = CheckOutcome(outcome, context);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].rule_id, "render/compile-error");
  EXPECT_EQ(mapped_line, 22u);  // header is 20 lines; `vec3 v = 1.0;` is the 2nd body line
  EXPECT_NE(found[0].message.find("float"), std::string::npos) << found[0].message;
}

TEST(IsolatedRender, AddressSpaceLimitMakesAClearCrash) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "sanitized builds render without an address-space limit";
#endif
  RenderOptions options = FastOptions();
  options.address_space_limit = uint64_t{64} << 20;  // too small for llvmpipe
  const RenderOutcome outcome = RenderIsolated(FragmentRequest(ShaderToyText(kGradient)), options);
  EXPECT_TRUE(outcome.status == RenderStatus::kCrashed ||
              outcome.status == RenderStatus::kContextFailed)
      << static_cast<int>(outcome.status) << outcome.message;
  EXPECT_FALSE(CheckOutcome(outcome, {}).empty());
}

TEST(IsolatedRender, EglBackendMatchesOsMesaWhenAvailable) {
  RenderOptions options = FastOptions();
  options.backend = BackendKind::kEgl;
  const RenderRequest request = FragmentRequest(ShaderToyText(kGradient));
  const RenderOutcome egl = RenderIsolated(request, options);
  if (egl.status == RenderStatus::kContextFailed) GTEST_SKIP() << egl.message;
  ASSERT_EQ(egl.status, RenderStatus::kOk) << egl.message;
  const RenderOutcome osmesa = RenderIsolated(request, FastOptions());
  ASSERT_EQ(osmesa.status, RenderStatus::kOk);
  EXPECT_EQ(
      0, std::memcmp(egl.pixels.data(), osmesa.pixels.data(), egl.pixels.size() * sizeof(float)));
}

}  // namespace
}  // namespace shaderport::render
