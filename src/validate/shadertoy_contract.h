// What shadertoy.com compiles for one pass: generated header, the user's Common
// and pass code, and a generated epilogue with the entry-point prototype and the
// site's main(). See docs in the .cpp for where this deviates from the site.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "model/channel_kind.h"
#include "model/pass_kind.h"
#include "source/source_manager.h"
#include "validate/glslang_validator.h"

namespace shaderport::validate {

// A kCommon `type` is the Common tab compiled on its own, as the site compiles it:
// a shorter header (iDate and iSampleRate only, no HW_PERFORMANCE) and a main() of
// its own.

// The generated texts (each ends with a newline).
std::string ShaderToyHeader(model::PassKind type, const model::ChannelKinds& channels);
std::string ShaderToyEpilogue(model::PassKind type);

// Entry point the site calls for a pass type, and its exact signature.
std::string_view EntryPointName(model::PassKind type);
std::string_view EntryPointSignature(model::PassKind type);

// Adds the generated texts to `sources` as synthetic files (so that an error in
// them has a location) and returns the request: header, `common` (if any), `pass`,
// epilogue; compiled as GLSL ES 3.00 and linked. `common` and `pass` must live in
// `sources` or otherwise outlive the request.
ValidationRequest ComposeShaderToyRequest(SourceManager& sources, model::PassKind type,
                                          const model::ChannelKinds& channels,
                                          const SourceFile* common, const SourceFile& pass);

// The lines Common (if any) and the pass start on in the text the site compiles (one
// string: header, Common, pass), which __LINE__ counts in: {Common's, the pass's}.
std::vector<int64_t> ShaderToyFirstLines(model::PassKind type, const SourceFile* common);

}  // namespace shaderport::validate
