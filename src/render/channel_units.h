// The texture and sampler behind each sampler uniform of one program. A ShaderToy
// project's passes each bind their own inputs with their own filter and wrap (as
// the site does); single-pass renders bind ShaderToyInputs::channels for every pass.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "render/gl_functions.h"
#include "render/render_request.h"

namespace shaderport::render {

// A ShaderToy buffer's latest output, bound instead of a channel texture.
struct ChannelOverride {
  GLuint texture = 0;  // 0: no override
  float width = 0;
  float height = 0;
};
using ChannelOverrides = std::array<ChannelOverride, 4>;

// The textures one program samples, one per texture unit, created on first use.
struct ProgramTextures {
  struct Unit {
    GLenum target = GL_TEXTURE_2D;
    GLuint name = 0;              // 0: nothing bound (samples (0, 0, 0, 1))
    GLuint sampler = 0;           // 0: the texture's own parameters
    int channel = -1;             // iChannelN, or -1 for another sampler
    bool follows_buffer = false;  // bound to the channel's ChannelOverride at every draw
    std::array<float, 3> size{};
  };
  bool created = false;
  std::vector<Unit> units;
};

// Creates what the sampler uniform `name` of GL type `type` reads. `channels` are
// the pass's own (PassChannelKind::kFromInputs: as single-pass renders bind them);
// `overrides` are the buffers its channels read now.
ProgramTextures::Unit CreateTextureUnit(const GlFunctions& gl, const std::string& name, GLenum type,
                                        const RenderRequest& request, const PassChannels& channels,
                                        const ChannelOverrides& overrides);

}  // namespace shaderport::render
