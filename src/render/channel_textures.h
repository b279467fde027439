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
// `user_image` may be empty; `vflip` turns it upright (the site's default). The
// texture is bound to the active texture unit.
BoundTexture CreateChannelTexture(const GlFunctions& gl, GLenum sampler_type,
                                  const ImageRgba8& user_image, bool vflip = true);

// The site's keyboard texture with no key down: 256x3 R8 zeros, no mipmaps (so
// it samples (0, 0, 0, 1)). Bound to the active texture unit.
BoundTexture CreateKeyboardTexture(const GlFunctions& gl);

// A sampler object with a project input's filter and wrap, as the site (and the
// project page) samples each input; it overrides the texture's own parameters.
GLuint CreateChannelSampler(const GlFunctions& gl, ChannelFilter filter, ChannelWrap wrap);

}  // namespace shaderport::render
