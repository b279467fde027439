#include "render/render_checks.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "render/mesa_log.h"
#include "render/shader_text.h"

namespace shaderport::render {
namespace {

// The site initialises the output to vec4(1e20): a pixel still this bright was
// never assigned by mainImage.
constexpr float kSiteInitialValue = 1e19f;

void AddCompileDiagnostics(const std::string& log, model::Stage stage, int pass,
                           const CheckContext& context, DiagnosticList& out) {
  const std::string stage_name = pass >= 0
                                     ? "buffer pass " + std::to_string(pass) + " fragment"
                                     : (stage == model::Stage::kVertex ? "vertex" : "fragment");
  bool any = false;
  for (const MesaLogEntry& entry : ParseMesaLog(log)) {
    if (!entry.is_error) continue;
    any = true;
    std::optional<SourceRange> range;
    if (entry.line > 0 && pass < 0 && context.map_line) range = context.map_line(stage, entry.line);
    if (entry.line > 0 && pass >= 0 && context.map_buffer_line) {
      range = context.map_buffer_line(pass, entry.line);
    }
    std::string message = "Mesa rejects the " + stage_name + " shader: " + entry.message;
    if (!range && entry.line > 0) {
      message += " (line " + std::to_string(entry.line) + " of the generated text)";
    }
    out.push_back(MakeDiagnostic(Severity::kError, "render/compile-error",
                                 range.value_or(context.anchor), std::move(message)));
  }
  if (!any) {
    out.push_back(MakeDiagnostic(Severity::kError, "render/compile-error", context.anchor,
                                 "Mesa rejects the " + std::string(stage_name) +
                                     " shader: " + (log.empty() ? std::string("(no log)") : log)));
  }
}

bool IsSentinel(const float* p) {
  return p[0] == kSentinel[0] && p[1] == kSentinel[1] && p[2] == kSentinel[2] &&
         p[3] == kSentinel[3];
}

uint8_t ToByte(float value) {
  if (!(value > 0.0f)) return 0;  // also NaN
  if (value >= 1.0f) return 255;
  return static_cast<uint8_t>(std::lround(value * 255.0f));
}

std::string At(const RenderOutcome& outcome, size_t pixel) {
  // Report in top-down picture coordinates, as the PNG shows them.
  const size_t x = pixel % outcome.width;
  const size_t y = outcome.height - 1 - pixel / outcome.width;
  return "(" + std::to_string(x) + ", " + std::to_string(y) + ")";
}

}  // namespace

ImageRgba8 ToImage(const RenderOutcome& outcome) {
  ImageRgba8 image;
  image.width = outcome.width;
  image.height = outcome.height;
  image.pixels.resize(size_t{outcome.width} * outcome.height * 4);
  const size_t row = size_t{outcome.width} * 4;
  for (uint32_t y = 0; y < outcome.height; ++y) {
    const float* src = &outcome.pixels[(outcome.height - 1 - y) * row];
    uint8_t* dst = &image.pixels[y * row];
    for (size_t i = 0; i < row; i += 4) {
      // A pixel never written (discarded) shows what a browser's canvas holds there:
      // the transparent black it was cleared to, not the check's sentinel.
      if (IsSentinel(&src[i])) continue;
      for (size_t c = 0; c < 4; ++c) dst[i + c] = ToByte(src[i + c]);
    }
  }
  return image;
}

DiagnosticList CheckPixels(const RenderOutcome& outcome, const CheckContext& context) {
  DiagnosticList out;
  const size_t count = size_t{outcome.width} * outcome.height;
  if (count == 0 || outcome.pixels.size() != count * 4) return out;
  size_t non_finite = 0, first_non_finite = 0, nan = 0;
  size_t sentinel = 0, first_sentinel = 0;
  size_t initial = 0, first_initial = 0;
  size_t valid = 0, black = 0, white = 0, zero = 0;
  bool single = true;
  uint8_t first_colour[4] = {};
  for (size_t i = 0; i < count; ++i) {
    const float* p = &outcome.pixels[i * 4];
    if (IsSentinel(p)) {
      if (sentinel++ == 0) first_sentinel = i;
      continue;
    }
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]) ||
        !std::isfinite(p[3])) {
      if (non_finite++ == 0) first_non_finite = i;
      if (std::isnan(p[0]) || std::isnan(p[1]) || std::isnan(p[2]) || std::isnan(p[3])) ++nan;
      continue;
    }
    if (p[0] >= kSiteInitialValue && p[1] >= kSiteInitialValue && p[2] >= kSiteInitialValue) {
      if (initial++ == 0) first_initial = i;
      continue;
    }
    const uint8_t c[4] = {ToByte(p[0]), ToByte(p[1]), ToByte(p[2]), ToByte(p[3])};
    if (valid++ == 0) {
      std::copy(c, c + 4, first_colour);
    } else if (!std::equal(c, c + 4, first_colour)) {
      single = false;
    }
    if (c[0] == 0 && c[1] == 0 && c[2] == 0) ++black;
    if (c[0] == 0 && c[1] == 0 && c[2] == 0 && c[3] == 0) ++zero;
    if (c[0] == 255 && c[1] == 255 && c[2] == 255) ++white;
  }
  const std::string of_total = " of " + std::to_string(count) + " pixels";
  // Browsers draw NaN as a colour that depends on the GPU (Chromium's SwiftShader
  // gives 0 or 255 depending on how the NaN arose); infinities clamp to 0 or 1 in
  // an 8-bit canvas, the same everywhere, but spread through float buffers.
  if (nan > 0) {
    out.push_back(MakeDiagnostic(Severity::kWarning, "render/nan-or-inf", context.anchor,
                                 std::to_string(nan) + of_total + " are NaN, first at " +
                                     At(outcome, first_non_finite) +
                                     ": browsers draw NaN in a colour that depends on the GPU"));
  } else if (non_finite > 0) {
    out.push_back(MakeDiagnostic(Severity::kNote, "render/nan-or-inf", context.anchor,
                                 std::to_string(non_finite) + of_total +
                                     " are infinite, first at " + At(outcome, first_non_finite) +
                                     ": an 8-bit canvas clamps them, float buffers keep them"));
  }
  if (initial > 0) {
    out.push_back(
        MakeDiagnostic(Severity::kError, "render/unwritten-pixels", context.anchor,
                       std::to_string(initial) + of_total +
                           " keep the site's initial value 1e20: the output was never assigned "
                           "there, first at " +
                           At(outcome, first_initial)));
  }
  if (context.expect_full_coverage && sentinel > 0) {
    out.push_back(MakeDiagnostic(Severity::kError, "render/unwritten-pixels", context.anchor,
                                 std::to_string(sentinel) + of_total +
                                     " were never written (discarded or not covered), first at " +
                                     At(outcome, first_sentinel)));
  } else if (!context.expect_full_coverage && sentinel == count) {
    out.push_back(
        MakeDiagnostic(Severity::kError, "render/unwritten-pixels", context.anchor,
                       "the vertex shader drew nothing on the generated mesh: every pixel "
                       "still holds the clear value"));
  }
  // Colour checks only on a picture that is not already reported as broken.
  const size_t drawn = count - sentinel;
  if (valid == 0 || valid != drawn || !context.expect_full_coverage) return out;
  if (zero == valid) {
    // llvmpipe leaves an output that is never assigned at zero or at register
    // leftovers near zero, alpha included; a real picture has some alpha.
    out.push_back(
        MakeDiagnostic(Severity::kError, "render/unwritten-pixels", context.anchor,
                       "every pixel is (0, 0, 0, 0): the output is probably never written"));
  } else if (black == valid) {
    out.push_back(
        MakeDiagnostic(Severity::kWarning, "render/all-black", context.anchor,
                       "the picture is entirely black: is fragColor assigned? Browsers start "
                       "an unassigned output at 0 (black), not at the site's initial 1e20"));
  } else if (white == valid) {
    out.push_back(
        MakeDiagnostic(Severity::kWarning, "render/blown-out", context.anchor,
                       "the picture is entirely white (blown out: values of 1.0 or more)"));
  } else if (single) {
    out.push_back(MakeDiagnostic(
        Severity::kWarning, "render/single-colour", context.anchor,
        "every pixel has the same colour rgba(" + std::to_string(first_colour[0]) + ", " +
            std::to_string(first_colour[1]) + ", " + std::to_string(first_colour[2]) + ", " +
            std::to_string(first_colour[3]) + ")"));
  }
  return out;
}

DiagnosticList CheckOutcome(const RenderOutcome& outcome, const CheckContext& context) {
  DiagnosticList out;
  switch (outcome.status) {
    case RenderStatus::kCompileFailed:
      if (outcome.vertex_log.find("error") != std::string::npos) {
        AddCompileDiagnostics(outcome.vertex_log, model::Stage::kVertex, outcome.failed_pass,
                              context, out);
      }
      if (outcome.fragment_log.find("error") != std::string::npos || out.empty()) {
        AddCompileDiagnostics(outcome.fragment_log, model::Stage::kFragment, outcome.failed_pass,
                              context, out);
      }
      return out;
    case RenderStatus::kLinkFailed:
      out.push_back(MakeDiagnostic(Severity::kError, "render/link-error", context.anchor,
                                   "Mesa cannot link the program: " + outcome.link_log));
      return out;
    case RenderStatus::kContextFailed:
      out.push_back(MakeDiagnostic(Severity::kError, "render/backend-unavailable", context.anchor,
                                   "no GL context to render with: " + outcome.message));
      return out;
    case RenderStatus::kTimeout:
      out.push_back(
          MakeDiagnostic(Severity::kError, "render/timeout", context.anchor, outcome.message));
      return out;
    case RenderStatus::kCrashed:
    case RenderStatus::kInternal:
      out.push_back(MakeDiagnostic(Severity::kError, "render/crashed", context.anchor,
                                   "the render failed: " + outcome.message));
      return out;
    case RenderStatus::kOk:
      break;
  }
  for (const std::string& error : outcome.gl_errors) {
    out.push_back(MakeDiagnostic(Severity::kError, "render/gl-error", context.anchor, error));
  }
  for (const std::string& name : UnusedOutputs(context.fragment_text)) {
    out.push_back(MakeDiagnostic(
        Severity::kError, "render/unwritten-pixels", context.anchor,
        "the fragment output '" + name + "' is never written, so every pixel is undefined"));
  }
  if (HasErrors(out)) return out;  // an undefined picture needs no further checks
  DiagnosticList pixels = CheckPixels(outcome, context);
  const size_t count = size_t{outcome.width} * outcome.height;
  const auto unassigned =
      static_cast<size_t>(std::max<int64_t>(outcome.unassigned_output_pixels, 0));
  if (unassigned > 0 && unassigned == count) {
    // The probe knows why the picture is black: say that instead of guessing.
    std::erase_if(pixels, [](const Diagnostic& d) { return d.rule_id == "render/all-black"; });
    out.push_back(MakeDiagnostic(
        Severity::kError, "render/unwritten-pixels", context.anchor,
        "the colour output (fragColor) is never assigned: browsers draw every pixel as 0 "
        "(they zero-initialise it; the site's initial 1e20 does not survive in Chromium), "
        "native GL, Vulkan and Metal leave it undefined"));
  } else if (unassigned > 0) {
    out.push_back(MakeDiagnostic(
        Severity::kWarning, "render/unassigned-output", context.anchor,
        std::to_string(unassigned) + " of " + std::to_string(count) +
            " pixels never assign the colour output (fragColor): browsers draw them as 0 "
            "(black, or transparent for a WebGL2 output), native targets leave them undefined; "
            "assign it on every path"));
  }
  out.insert(out.end(), pixels.begin(), pixels.end());
  return out;
}

}  // namespace shaderport::render
