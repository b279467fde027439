// Driver glue for smoke rendering: composes what the browser or shadertoy.com would
// compile (validate/shadertoy_contract.h for ShaderToy passes), renders it in an
// isolated child (render/isolated_render.h) and turns the outcome into diagnostics
// on the user's lines. Used by `shaderport render` and the check pipeline.
#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "diag/diagnostic.h"
#include "driver/dialect.h"
#include "model/harness_dialect.h"
#include "render/render_checks.h"
#include "render/render_request.h"
#include "source/source_manager.h"
#include "validate/shadertoy_contract.h"

namespace shaderport::driver {

struct RenderFileOptions {
  render::RenderOptions render;  // backend, timeout, address-space limit, cache
  render::RenderRequest base;    // size, frames and ShaderToy inputs; sources are ignored
  std::array<std::string, 4> channel_images;  // PNG paths for iChannel0..3 ("" = procedural)
  model::ChannelKinds channel_types{};        // sampler kind per channel (ShaderToy)
  // Which channel_types the user gave; RenderFile decides the others from the code
  // (file_decision.h), as every command does.
  std::array<bool, 4> channel_types_given{};
  // The host that completes non-ShaderToy code (a harness dialect), if any.
  const model::HarnessDialect* harness = nullptr;
  const SourceFile* common = nullptr;  // ShaderToy Common code, if any
  // Where the WebGL2 port of WebGL1 code is registered; RenderFile sets it.
  SourceManager* sources = nullptr;
  // Apply what browsers do to WebGL shaders before Mesa compiles them (zero
  // initialisation, index clamping); false draws what a native driver would.
  bool webgl_semantics = true;
  // With the browser semantics: also run the optimiser Chromium's SwiftShader runs
  // (spirv-opt -O) on the text, for its regroupings of float arithmetic. Off by
  // default: it doubles a render's time and measured no better (docs/render.md).
  bool browser_optimiser = false;
};

struct RenderFileResult {
  const SourceFile* file = nullptr;         // null when the file could not be read
  std::string dialect;                      // "shadertoy", "webgl1", "webgl2"
  std::string stage;                        // "vertex", "fragment"
  DiagnosticList diagnostics;               // render/* (and input/* when unreadable)
  std::optional<render::ImageRgba8> image;  // the final frame, when something was drawn
  double milliseconds = 0;
};

// Reads, decides what the file is (file_decision.h), renders and checks one file.
RenderFileResult RenderFile(const std::filesystem::path& path, SourceManager& sources,
                            const RenderFileOptions& options);

// The resource-limit breaches of `file` (with `common`, ShaderToy's Common code) as the
// front end finds them: text past a limit is not drawn, as `check` does not compile it.
DiagnosticList RenderLimitBreaches(const SourceFile& file, const DetectedKind& kind,
                                   const SourceFile* common, SourceManager& sources);

// Renders a file already read, whose dialect and stage the caller has decided
// (the check pipeline).
void RenderSource(const SourceFile& file, const DetectedKind& kind,
                  const RenderFileOptions& options, RenderFileResult& result);

// For callers that compose the text themselves (the port pipeline): complete
// `#version 300 es` texts and a map from their lines to the user's source.
struct PreparedShader {
  std::string vertex_text;         // empty: built-in full-screen triangle
  std::string fragment_text;       // empty: built-in flat shader (vertex drawn on a mesh)
  bool fullscreen_vertex = false;  // vertex_text draws the full-screen triangle
  std::function<std::optional<SourceRange>(model::Stage, uint32_t)> map_line;
  // Lines of RenderFileOptions::base.buffer_passes[pass] (ShaderToy multipass).
  std::function<std::optional<SourceRange>(int pass, uint32_t)> map_buffer_line;
  SourceRange anchor;                // where picture-level findings point
  const SourceFile* user = nullptr;  // scanned for loops over llvmpipe's cap
  // main() sets the output's alpha itself (a ShaderToy Image pass forces 1): the
  // render probe can travel in it, and the draw needs one colour target.
  bool main_sets_alpha = false;
};
void RenderPrepared(const PreparedShader& shader, const RenderFileOptions& options,
                    RenderFileResult& result);

}  // namespace shaderport::driver
