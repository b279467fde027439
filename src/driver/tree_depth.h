// How deeply a shader's syntax tree nests: glslang's SPIR-V generator (port --emit,
// render --browser-optimiser) recurses once per level, and a chain `a+a+...` of
// 400,000 terms (800 KB) overflowed its 256 MiB stack (SIGSEGV).
#pragma once

#include <cstdint>
#include <string_view>

namespace shaderport::driver {

// The depth of the deepest node of `text` parsed alone as GLSL ES `version` (the
// translation unit is depth 0). Walks without recursion.
uint32_t SyntaxTreeDepth(std::string_view text, int version = 300);

}  // namespace shaderport::driver
