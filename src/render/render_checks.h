// Turns a render outcome into diagnostics: Mesa compile/link errors mapped back to
// the user's lines, GL errors, killed or crashed renders, and picture checks (NaN or
// Inf, pixels never written, a single colour, all black, blown out to white).
#pragma once

#include <functional>
#include <optional>
#include <string_view>

#include "diag/diagnostic.h"
#include "model/stage.h"
#include "render/render_request.h"

namespace shaderport::render {

struct CheckContext {
  // Where diagnostics without a line point: normally the whole user file.
  SourceRange anchor;
  // Maps a 1-based line of the text given to Mesa to the user's source; nullopt
  // when the line is generated (a header or wrapper). Unset: everything at anchor.
  std::function<std::optional<SourceRange>(model::Stage stage, uint32_t line)> map_line;
  // The same for the text of buffer pass `pass` (RenderRequest::buffer_passes).
  std::function<std::optional<SourceRange>(int pass, uint32_t line)> map_buffer_line;
  // False for a vertex shader drawn on the generated mesh, which covers only part
  // of the picture: then only an empty picture counts as unwritten.
  bool expect_full_coverage = true;
  // The fragment text as rendered, when known: an `out` variable it never mentions
  // again is reported as unwritten (llvmpipe leaves such an output undefined, so
  // the picture alone cannot show it reliably).
  std::string_view fragment_text;
};

DiagnosticList CheckOutcome(const RenderOutcome& outcome, const CheckContext& context);

// Picture checks alone (part of CheckOutcome), on RGBA32F pixels.
DiagnosticList CheckPixels(const RenderOutcome& outcome, const CheckContext& context);

// The picture as the site would show it: clamped, rounded to 8 bits, rows top-down.
ImageRgba8 ToImage(const RenderOutcome& outcome);

}  // namespace shaderport::render
