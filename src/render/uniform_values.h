// Values for every active uniform of a linked program: ShaderToy's by name, and
// sensible defaults by name and type for others (perspective for *Projection*,
// a camera a few units back for *View*, identity for other matrices).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "render/channel_units.h"
#include "render/gl_functions.h"
#include "render/render_request.h"

namespace shaderport::render {

// Texture units SetUniforms binds samplers to, at most (further samplers stay unbound).
inline constexpr int kMaxTextureUnits = 16;

// Sets all active uniforms for frame `frame_index` (0-based) and binds the
// program's textures and samplers to their units (programs share units, so every
// draw rebinds). `channels` are the pass's own inputs (channel_units.h).
void SetUniforms(const GlFunctions& gl, GLuint program, const RenderRequest& request,
                 int frame_index, ProgramTextures& textures, const PassChannels& channels,
                 const ChannelOverrides& overrides = {});

// The ShaderToy uniforms render knows how to feed, by the names of
// rules/dialects/shadertoy.toml (a test holds them to exactly the TOML's uniforms).
std::vector<std::string_view> FedShaderToyUniforms();

// Column-major 4x4 matrices, exposed for tests.
std::vector<float> PerspectiveMatrix(float aspect);
std::vector<float> ViewMatrix();

}  // namespace shaderport::render
