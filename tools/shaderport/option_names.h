// The closed sets of option values the commands take, for "did you mean" and
// for the list an unknown value's error gives.
#pragma once

#include <array>
#include <string>

namespace shaderport::cli {

inline const std::array<std::string, 4> kFormatNames = {"text", "json", "sarif", "github"};
inline const std::array<std::string, 3> kDialectNames = {"shadertoy", "webgl1", "webgl2"};
inline const std::array<std::string, 2> kTargetNames = {"webgl1", "webgl2"};
inline const std::array<std::string, 2> kStageNames = {"vertex", "fragment"};
inline const std::array<std::string, 3> kSeverityNames = {"error", "warning", "note"};
inline const std::array<std::string, 3> kWhenNames = {"auto", "always", "never"};  // --color
inline const std::array<std::string, 9> kEmitNames = {
    "essl", "spirv", "spvasm", "hlsl", "msl", "essl-roundtrip", "reflect", "html", "folder"};
inline const std::array<std::string, 2> kBackendNames = {"osmesa", "egl"};
inline const std::array<std::string, 2> kMergeFormatNames = {"json", "sarif"};

}  // namespace shaderport::cli
