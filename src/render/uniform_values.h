// Values for every active uniform of a linked program: ShaderToy's by name, and
// sensible defaults by name and type for others (perspective for *Projection*,
// a camera a few units back for *View*, identity for other matrices).
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
    GLuint name = 0;
    int channel = -1;  // iChannelN, or -1 for another sampler
    std::array<float, 3> size{};
  };
  bool created = false;
  std::vector<Unit> units;
};

// Sets all active uniforms for frame `frame_index` (0-based) and binds the
// program's textures to their units (programs share units, so every draw rebinds).
void SetUniforms(const GlFunctions& gl, GLuint program, const RenderRequest& request,
                 int frame_index, ProgramTextures& textures,
                 const ChannelOverrides& overrides = {});

// Column-major 4x4 matrices, exposed for tests.
std::vector<float> PerspectiveMatrix(float aspect);
std::vector<float> ViewMatrix();

}  // namespace shaderport::render
