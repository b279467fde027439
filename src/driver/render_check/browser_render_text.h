// The text Mesa compiles for a render: the complete shader with what browsers do
// to WebGL shaders applied (glsl/webgl_semantics), so that the picture is the
// page's. The user's file and the port output are never changed.
#pragma once

#include <string>
#include <string_view>

#include "source/edit.h"

namespace shaderport::driver {

struct BrowserRenderTextOptions {
  bool webgl_semantics = true;  // zero initialisation (out parameters too) and index clamping
  // Also compute as desktop GPUs do where llvmpipe differs (32-bit mediump, smoothstep
  // with equal edges). Off for the SPIR-V leg, whose output keeps the user's precision.
  bool desktop_gpu_arithmetic = true;
  // Built-in math and float division as Chromium computes them without a GPU
  // (SwiftShader), bit for bit. Renders only: never in text a user receives.
  bool cpu_browser_math = false;
  // For text that goes through the SPIR-V optimiser (BrowserSemanticsOptions).
  bool opaque_helper_arguments = false;
  bool add_render_probe = false;  // loop counts and output writes (main fragment pass)
  bool probe_in_alpha = false;    // ... in the output's alpha (main() sets alpha itself)
  bool vertex_stage = false;
};

// Lines keep their places, so maps from Mesa's line numbers stay valid. Text that
// does not parse cleanly is returned as it is (Mesa then reports the error).
std::string BrowserRenderText(std::string_view text, const BrowserRenderTextOptions& options);

// The same, with the map from the edited text back to `text` (for the SPIR-V leg,
// whose diagnostics must still reach the user's columns).
EditResult BrowserRenderTextWithMap(std::string_view text, const BrowserRenderTextOptions& options);

// The same, saying whether the probe went into the output's alpha (probe_in_alpha is
// a request; a main() that may return early, or whose end cannot be edited, keeps the
// second output).
struct ProbedRenderText {
  std::string text;
  bool probe_in_alpha = false;
};
ProbedRenderText BrowserRenderTextWithProbe(std::string_view text,
                                            const BrowserRenderTextOptions& options);

}  // namespace shaderport::driver
