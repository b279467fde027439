// llvmpipe silently stops every loop after 65535 iterations in total per shader
// invocation (toolchain-facts §4), so a picture from a shader that may loop longer
// proves nothing. This scan estimates iteration counts from the text: literal or
// #define'd bounds of nested for loops, and loops with no visible bound.
#pragma once

#include "diag/diagnostic.h"
#include "render/render_request.h"
#include "source/source_file.h"

namespace shaderport::render {

inline constexpr uint64_t kLlvmpipeLoopCap = 65535;

// Notes (render/loop-cap) at the loops that may exceed the cap.
DiagnosticList LoopCapNotes(const SourceFile& file);

// What the render's loop probe measured (RenderOutcome::max_loop_iterations): a
// warning (render/loop-cap) at the loops the text scan suspects, or at `anchor`,
// when pixels reached the cap; nothing when none did; the text scan's notes when
// the probe could not be added.
DiagnosticList LoopCapFindings(const SourceFile& file, const RenderOutcome& outcome,
                               const SourceRange& anchor);

}  // namespace shaderport::render
