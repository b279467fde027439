// What browsers do to every WebGL shader before a driver sees it, done to our own
// tree as byte edits, so that a native GL (Mesa) or SPIR-V compile of the text
// behaves as the page would. Copies ANGLE's WebGL translation
// (src/compiler/translator/tree_ops in ANGLE):
//  - InitializeUninitializedLocals / DeferGlobalInitializers: locals and globals
//    without an initializer start at zero;
//  - initOutputVariables / initGLPosition: shader outputs start at zero;
//  - a non-void function that runs off its end returns zero (measured);
//  - ClampIndirectIndices: a non-constant index into a vector, matrix or sized
//    array is clamped into range, for reads and writes;
// and where llvmpipe computes differently from desktop GPUs:
//  - mediump and lowp are computed at 32 bits (Mesa lowers mediump to 16);
//  - smoothstep(a, b, x) with a == b is the step GPUs draw (llvmpipe's fast math
//    folds it into garbage; GLSL leaves it undefined);
// and, on request, where llvmpipe computes differently from Chromium without a GPU:
//  - sin, cos, exp, pow, dot, mix, ... computed as SwiftShader computes them, and
//    float divisions kept as divisions (cpu_browser_math.cpp);
//  - fragment outputs declared invariant, so that Mesa adds in source order
//    (source_order_arithmetic.cpp);
//  - lines inside skipped #if groups are emptied (Mesa rejects a misspelled
//    directive there; browsers skip it);
// plus, on request, a probe written to a second fragment output (or to the colour
// output's alpha), so that a render can tell when llvmpipe's silent loop cap was
// reached and which pixels never assigned the colour output.
// See docs/browser-divergence.md ("Rendering") for each transform.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "source/edit.h"
#include "source/source_file.h"

namespace shaderport::glsl {

// The fragment output (location 1) of the render probe: .x = loop body executions
// of the pixel's invocation (what llvmpipe caps at 65535), .y = 1 where the colour
// output was assigned; .z is a sink for branch conditions (source_order_arithmetic).
// With probe_in_alpha it is a variable, and the end of main() writes the colour
// output's alpha as .x where .y is 1 and -1 - .x where it is 0 (decoded by
// ReadAlphaProbe, src/render/gl_renderer.cpp).
inline constexpr std::string_view kRenderProbeOutput = "shaderport_probe";

struct BrowserSemanticsOptions {
  bool zero_initialize = true;  // locals, globals, outputs
  bool zero_out_parameters = false;
  bool clamp_indices = true;
  // smoothstep(a, a, x) as GPUs compute it (a step), not as llvmpipe folds it.
  bool gpu_smoothstep_edges = true;
  // mediump and lowp computed at 32 bits, as desktop browsers do (Mesa uses 16).
  bool promote_precision = true;
  // Built-in math and division as Chromium computes them on the CPU (SwiftShader),
  // so that hash noise draws the same bits. For renders, never for output text.
  bool cpu_browser_math = false;
  // Fragment outputs declared invariant, so that Mesa keeps float arithmetic in
  // source order as Chromium does (it regroups sums otherwise). For renders only.
  bool source_order_arithmetic = false;
  // The math helpers' parameters pass through the opaque zero even where the above
  // and the probe's conditions already keep arithmetic exact for Mesa: the SPIR-V
  // optimiser (render --browser-optimiser) ignores invariance.
  bool opaque_helper_arguments = false;
  // Lines of skipped #if groups emptied (conditional directives kept): browsers
  // ignore them, Mesa rejects a bad directive there.
  bool empty_inactive_lines = true;
  bool add_render_probe = false;  // fragment shaders only
  // The probe travels in the colour output's alpha instead of a second output, for a
  // main() that writes alpha itself (a ShaderToy Image pass forces it to 1): the render
  // then has one colour target, and llvmpipe compiles the store of one, not two.
  bool probe_in_alpha = false;
  bool vertex_stage = false;
};

struct BrowserSemanticsResult {
  std::vector<std::string> texts;     // one per input part, edited (or as given)
  std::vector<SourceMap> maps;        // per part: edited text -> the part as given
  bool applied = false;               // false: the text did not parse cleanly, left unchanged
  bool render_probe = false;          // the probe output was added
  bool probe_in_alpha = false;        // ... as a variable written to the output's alpha
  bool tracks_output_writes = false;  // ... and its .y marks colour-output writes
  uint32_t initialized = 0;           // variables given a zero initial value
  uint32_t default_returns = 0;       // `return <zero>;` added at the end of functions
  uint32_t clamped = 0;               // indices clamped
  uint32_t smoothsteps = 0;           // smoothstep names renamed to the GPU-faithful helper
  uint32_t promoted = 0;              // mediump / lowp keywords made highp
  uint32_t math_calls = 0;            // built-in calls renamed to the CPU-browser helpers
  uint32_t divisions = 0;             // divisions by constants made multiplications
  uint32_t opaque_divisors = 0;       // other float divisors hidden from Mesa's folding
  uint32_t conversions = 0;           // uint to float conversions done in two roundings
  uint32_t folded_clamps = 0;         // clamp(c, lo, hi) answered from c and one bound
  uint32_t counted_loops = 0;         // loops instrumented
  uint32_t invariant_outputs = 0;     // fragment outputs declared invariant
  uint32_t exposed_conditions = 0;    // branch conditions also written to the probe
  uint32_t skipped = 0;               // places inside macros that could not be edited safely
};

// `parts` are preprocessed as one translation unit (e.g. a generated header, Common,
// the pass, a generated main()). Edits never add or remove a line, so line maps
// made for the unedited parts stay valid.
BrowserSemanticsResult ApplyBrowserSemantics(std::span<const SourceFile* const> parts,
                                             const BrowserSemanticsOptions& options);

}  // namespace shaderport::glsl
