#include "driver/render_check/browser_render_text.h"

#include <array>

#include "glsl/webgl_semantics/browser_semantics.h"
#include "source/source_manager.h"

namespace shaderport::driver {

namespace {

glsl::BrowserSemanticsResult Apply(std::string_view text, const BrowserRenderTextOptions& options) {
  glsl::BrowserSemanticsOptions semantics;
  semantics.zero_initialize = options.webgl_semantics;
  semantics.clamp_indices = options.webgl_semantics;
  semantics.gpu_smoothstep_edges = options.webgl_semantics && options.desktop_gpu_arithmetic;
  semantics.promote_precision = options.webgl_semantics && options.desktop_gpu_arithmetic;
  semantics.zero_out_parameters = options.webgl_semantics;
  semantics.cpu_browser_math = options.webgl_semantics && options.cpu_browser_math;
  semantics.source_order_arithmetic = semantics.cpu_browser_math;
  semantics.opaque_helper_arguments = options.opaque_helper_arguments;
  semantics.add_render_probe = options.add_render_probe;
  semantics.probe_in_alpha = options.probe_in_alpha;
  semantics.vertex_stage = options.vertex_stage;
  SourceManager local;  // the transform needs a file with an id
  const SourceFile& file = local.Add("<render>", std::string(text), true);
  const std::array<const SourceFile*, 1> parts = {&file};
  return glsl::ApplyBrowserSemantics(parts, semantics);
}

}  // namespace

EditResult BrowserRenderTextWithMap(std::string_view text,
                                    const BrowserRenderTextOptions& options) {
  glsl::BrowserSemanticsResult result = Apply(text, options);
  return {std::move(result.texts.front()), std::move(result.maps.front())};
}

ProbedRenderText BrowserRenderTextWithProbe(std::string_view text,
                                            const BrowserRenderTextOptions& options) {
  glsl::BrowserSemanticsResult result = Apply(text, options);
  return {std::move(result.texts.front()), result.probe_in_alpha};
}

std::string BrowserRenderText(std::string_view text, const BrowserRenderTextOptions& options) {
  return BrowserRenderTextWithMap(text, options).text;
}

}  // namespace shaderport::driver
