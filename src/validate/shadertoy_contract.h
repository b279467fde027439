// What shadertoy.com compiles for one pass: generated header, the user's Common
// and pass code, and a generated epilogue with the entry-point prototype and the
// site's main(). See docs in the .cpp for where this deviates from the site.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "source/source_manager.h"
#include "validate/glslang_validator.h"

namespace shaderport::validate {

enum class PassType { kImage, kBuffer, kCube, kSound };
enum class ChannelType { k2D, kCube, k3D };
using ChannelTypes = std::array<ChannelType, 4>;  // iChannel0..3; default all k2D

// From the ShaderToy JSON names: "image", "buffer", "cube", "sound" (nullopt otherwise,
// e.g. "common", which is not a pass of its own).
std::optional<PassType> PassTypeFromName(std::string_view name);
const char* PassTypeName(PassType type);
// From an input's `ctype`: "cubemap" -> kCube, "volume" -> k3D, everything else
// (texture, buffer, keyboard, video, music...) is sampled as a sampler2D.
ChannelType ChannelTypeFromCtype(std::string_view ctype);

// The generated texts (each ends with a newline).
std::string ShaderToyHeader(PassType type, const ChannelTypes& channels);
std::string ShaderToyEpilogue(PassType type);

// Entry point the site calls for a pass type, and its exact signature.
std::string_view EntryPointName(PassType type);
std::string_view EntryPointSignature(PassType type);

// Adds the generated texts to `sources` as synthetic files (so that an error in
// them has a location) and returns the request: header, `common` (if any), `pass`,
// epilogue; compiled as GLSL ES 3.00 and linked. `common` and `pass` must live in
// `sources` or otherwise outlive the request.
ValidationRequest ComposeShaderToyRequest(SourceManager& sources, PassType type,
                                          const ChannelTypes& channels, const SourceFile* common,
                                          const SourceFile& pass);

}  // namespace shaderport::validate
