// Renders what `shaderport port` produced: the ported WebGL2 text drawn as a plain
// `#version 300 es` shader (a fragment shader on the full-screen triangle, a vertex
// shader on the generated mesh), with Mesa's lines mapped back to the user's file.
#pragma once

#include <string_view>

#include "driver/port/port_file.h"
#include "driver/render_check/render_file.h"

namespace shaderport::driver {

// The sampler kind of each `iChannelN` the text declares (`uniform samplerCube
// iChannel1;`), so that the renderer binds a texture of the same kind; channels the
// text does not declare keep `fallback`'s kind.
model::ChannelKinds ChannelTypesOf(std::string_view text, model::ChannelKinds fallback = {});

// `result` must hold ported text (not read_failed). Channel kinds come from the
// ported text's declarations; `options` gives everything else.
RenderFileResult RenderPortResult(const PortResult& result, const RenderFileOptions& options);

}  // namespace shaderport::driver
