// How a ShaderToy channel (iChannel0..3) is sampled. Where the kind may be left for
// the code to decide (inferred from how it samples the channel), it is a
// std::optional<ChannelKind>: nullopt means "not given", there is no kAuto.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace shaderport::model {

// sampler2D, samplerCube, sampler3D. The values are written to the render child's
// pipe (render/request_wire.cpp): keep them.
enum class ChannelKind : uint8_t { k2D, kCube, k3D };

using ChannelKinds = std::array<ChannelKind, 4>;  // iChannel0..3; default all k2D
// Per channel: the kind the user or a project gave, nullopt where the code decides.
using GivenChannelKinds = std::array<std::optional<ChannelKind>, 4>;

// "2d", "cube", "3d": as --channel and explain-file spell a channel's sampler type.
std::string_view ChannelKindName(ChannelKind kind);
std::optional<ChannelKind> ParseChannelKind(std::string_view name);
// "sampler2D", "samplerCube", "sampler3D": the GLSL type a channel is declared with.
std::string_view SamplerTypeName(ChannelKind kind);

// From a ShaderToy input's `ctype`: "cubemap" -> kCube, "volume" -> k3D, everything
// else (texture, buffer, keyboard, video, music...) is sampled as a sampler2D.
ChannelKind ChannelKindFromCtype(std::string_view ctype);

}  // namespace shaderport::model
