#include "render/channel_textures.h"

#include <algorithm>

#include "render/procedural_textures.h"

namespace shaderport::render {
namespace {

void SetSampling(const GlFunctions& gl, GLenum target, GLenum wrap) {
  gl.TexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  gl.TexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.TexParameteri(target, GL_TEXTURE_WRAP_S, wrap);
  gl.TexParameteri(target, GL_TEXTURE_WRAP_T, wrap);
  gl.TexParameteri(target, GL_TEXTURE_WRAP_R, wrap);
  gl.GenerateMipmap(target);
}

}  // namespace

BoundTexture CreateChannelTexture(const GlFunctions& gl, GLenum sampler_type,
                                  const ImageRgba8& user_image, bool vflip) {
  BoundTexture bound;
  const GLenum target = TextureTargetOf(sampler_type);
  bound.target = target;
  gl.GenTextures(1, &bound.name);
  gl.BindTexture(target, bound.name);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (target == GL_TEXTURE_CUBE_MAP) {
    const uint32_t size = kProceduralCubeSize;
    for (uint32_t face = 0; face < 6; ++face) {
      const auto texels = ProceduralCubeFace(face, size);
      gl.TexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA8, size, size, 0, GL_RGBA,
                    GL_UNSIGNED_BYTE, texels.data());
    }
    bound.width = bound.height = static_cast<float>(size);
    SetSampling(gl, target, GL_CLAMP_TO_EDGE);
    return bound;
  }
  if (target == GL_TEXTURE_3D || target == GL_TEXTURE_2D_ARRAY) {
    const uint32_t size = kProcedural3DSize;
    const auto texels = Procedural3D(size);
    gl.TexImage3D(target, 0, GL_RGBA8, size, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                  texels.data());
    bound.width = bound.height = bound.depth = static_cast<float>(size);
    SetSampling(gl, target, GL_REPEAT);
    return bound;
  }
  if (!user_image.pixels.empty()) {
    // ShaderToy flips images vertically by default so that they appear upright:
    // GL's row 0 is the bottom row, PNG's the top one.
    const size_t row = size_t{user_image.width} * 4;
    std::vector<uint8_t> flipped(user_image.pixels.size());
    for (uint32_t y = 0; y < user_image.height; ++y) {
      const uint32_t from = vflip ? user_image.height - 1 - y : y;
      std::copy_n(&user_image.pixels[from * row], row, &flipped[y * row]);
    }
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, user_image.width, user_image.height, 0, GL_RGBA,
                  GL_UNSIGNED_BYTE, flipped.data());
    bound.width = static_cast<float>(user_image.width);
    bound.height = static_cast<float>(user_image.height);
  } else {
    const uint32_t size = kProcedural2DSize;
    const auto texels = Procedural2D(size);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                  texels.data());
    bound.width = bound.height = static_cast<float>(size);
  }
  SetSampling(gl, GL_TEXTURE_2D, GL_REPEAT);
  return bound;
}

BoundTexture CreateKeyboardTexture(const GlFunctions& gl) {
  constexpr GLsizei kKeys = 256;
  constexpr GLsizei kRows = 3;  // down, pressed this frame, toggled
  const std::vector<uint8_t> zeros(size_t{kKeys} * kRows, 0);
  BoundTexture bound;
  gl.GenTextures(1, &bound.name);
  gl.BindTexture(GL_TEXTURE_2D, bound.name);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R8, kKeys, kRows, 0, GL_RED, GL_UNSIGNED_BYTE, zeros.data());
  bound.width = kKeys;
  bound.height = kRows;
  return bound;
}

GLuint CreateChannelSampler(const GlFunctions& gl, ChannelFilter filter, ChannelWrap wrap) {
  GLuint sampler = 0;
  gl.GenSamplers(1, &sampler);
  const GLint min = filter == ChannelFilter::kNearest  ? GL_NEAREST
                    : filter == ChannelFilter::kLinear ? GL_LINEAR
                                                       : GL_LINEAR_MIPMAP_LINEAR;
  gl.SamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, min);
  gl.SamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER,
                       filter == ChannelFilter::kNearest ? GL_NEAREST : GL_LINEAR);
  const GLint mode = wrap == ChannelWrap::kClamp ? GL_CLAMP_TO_EDGE : GL_REPEAT;
  gl.SamplerParameteri(sampler, GL_TEXTURE_WRAP_S, mode);
  gl.SamplerParameteri(sampler, GL_TEXTURE_WRAP_T, mode);
  gl.SamplerParameteri(sampler, GL_TEXTURE_WRAP_R, mode);
  return sampler;
}

GLenum TextureTargetOf(GLenum sampler_type) {
  switch (sampler_type) {
    case GL_SAMPLER_CUBE:
    case GL_SAMPLER_CUBE_SHADOW:
    case GL_INT_SAMPLER_CUBE:
    case GL_UNSIGNED_INT_SAMPLER_CUBE:
      return GL_TEXTURE_CUBE_MAP;
    case GL_SAMPLER_3D:
    case GL_INT_SAMPLER_3D:
    case GL_UNSIGNED_INT_SAMPLER_3D:
      return GL_TEXTURE_3D;
    case GL_SAMPLER_2D_ARRAY:
    case GL_SAMPLER_2D_ARRAY_SHADOW:
    case GL_INT_SAMPLER_2D_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_2D_ARRAY:
      return GL_TEXTURE_2D_ARRAY;
    default:
      return GL_TEXTURE_2D;
  }
}

}  // namespace shaderport::render
