#include "render/channel_units.h"

#include "render/channel_textures.h"

namespace shaderport::render {
namespace {

int ChannelOfName(const std::string& name) {
  if (name.size() == 9 && name.starts_with("iChannel") && name[8] >= '0' && name[8] <= '3')
    return name[8] - '0';
  return -1;
}

// As before per-pass channels existed: the channel's override (a buffer) when it has
// one, else nothing when the record left it unbound, else the user's image or a
// procedural texture of the sampler's kind.
ProgramTextures::Unit FromInputs(const GlFunctions& gl, GLenum type, int channel,
                                 const RenderRequest& request, const ChannelOverrides& overrides) {
  ProgramTextures::Unit entry;
  entry.channel = channel;
  entry.follows_buffer = channel >= 0;
  const auto c = static_cast<size_t>(channel);
  const bool overridden = channel >= 0 && overrides[c].texture != 0;
  const bool unbound = channel >= 0 && request.inputs.channels[c].unbound;
  if (unbound && !overridden) {
    entry.target = TextureTargetOf(type);  // texture 0: incomplete, samples (0,0,0,1)
  } else if (!overridden) {
    static const ImageRgba8 kNoImage;
    const BoundTexture bound =
        CreateChannelTexture(gl, type, channel >= 0 ? request.inputs.channels[c].image : kNoImage);
    entry.target = bound.target;
    entry.name = bound.name;
    entry.size = {bound.width, bound.height, bound.depth};
  }
  return entry;
}

// The texture target a project input of this kind is bound to.
GLenum TargetOf(PassChannelKind kind) {
  if (kind == PassChannelKind::kCube) return GL_TEXTURE_CUBE_MAP;
  if (kind == PassChannelKind::kVolume) return GL_TEXTURE_3D;
  return GL_TEXTURE_2D;
}

}  // namespace

ProgramTextures::Unit CreateTextureUnit(const GlFunctions& gl, const std::string& name, GLenum type,
                                        const RenderRequest& request, const PassChannels& channels,
                                        const ChannelOverrides& overrides) {
  const int channel = ChannelOfName(name);
  if (channel < 0 || channels[static_cast<size_t>(channel)].kind == PassChannelKind::kFromInputs)
    return FromInputs(gl, type, channel, request, overrides);
  const PassChannel& input = channels[static_cast<size_t>(channel)];
  ProgramTextures::Unit entry;
  entry.channel = channel;
  entry.target = TextureTargetOf(type);
  // A texture of another target on the unit leaves the shader's sampler reading
  // nothing, as in the browser when the header and the input disagree.
  if (input.kind == PassChannelKind::kUnbound || TargetOf(input.kind) != entry.target) return entry;
  if (input.kind == PassChannelKind::kBuffer) {
    entry.follows_buffer = true;
  } else if (input.kind == PassChannelKind::kKeyboard) {
    const BoundTexture bound = CreateKeyboardTexture(gl);
    entry.name = bound.name;
    entry.size = {bound.width, bound.height, bound.depth};
  } else {
    const ImageRgba8& image = request.inputs.channels[static_cast<size_t>(channel)].image;
    const BoundTexture bound = CreateChannelTexture(
        gl, type, input.kind == PassChannelKind::kTexture ? image : ImageRgba8{}, input.vflip);
    entry.name = bound.name;
    entry.size = {bound.width, bound.height, bound.depth};
  }
  // The keyboard texture has no mipmaps (the page reads it linearly then); cube
  // maps are seamless in WebGL2, which clamping comes closest to in desktop GL.
  const ChannelFilter filter =
      input.kind == PassChannelKind::kKeyboard && input.filter == ChannelFilter::kMipmap
          ? ChannelFilter::kLinear
          : input.filter;
  const ChannelWrap wrap = input.kind == PassChannelKind::kCube ? ChannelWrap::kClamp : input.wrap;
  entry.sampler = CreateChannelSampler(gl, filter, wrap);
  return entry;
}

}  // namespace shaderport::render
