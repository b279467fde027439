// Creates the GL texture a sampler uniform reads: the user's image for a ShaderToy
// channel, or a procedural texture of the sampler's kind (2D, cube, 3D).
#pragma once

#include "render/gl_functions.h"
#include "render/render_request.h"

namespace shaderport::render {

struct BoundTexture {
  GLenum target = GL_TEXTURE_2D;
  GLuint name = 0;
  float width = 0;
  float height = 0;
  float depth = 1;
};

// The texture target a sampler of this GL type reads (GL_TEXTURE_CUBE_MAP for
// GL_SAMPLER_CUBE, ...).
GLenum TextureTargetOf(GLenum sampler_type);

// `sampler_type` is the uniform's GL type (GL_SAMPLER_2D, GL_SAMPLER_CUBE, ...);
// `user_image` may be empty. The texture is bound to the active texture unit.
BoundTexture CreateChannelTexture(const GlFunctions& gl, GLenum sampler_type,
                                  const ImageRgba8& user_image);

}  // namespace shaderport::render
