// GLSL ES 1.00 Appendix A as WebGL enforces it (in WebGL 1 and for GLSL ES 1.00
// shaders in WebGL 2): the for-loop form and the loop indices it defines.
#pragma once

#include <set>

#include "rule/rule_context.h"

namespace shaderport::rules::webgl {

// Appendix A applies to GLSL ES 1.00 code in either WebGL version.
bool AppendixAApplies(const rule::RuleContext& context);

// The symbols declared by the init of every for loop of the shader whose
// header has Appendix A's form (`for (int i = c; ...)`).
std::set<uint32_t> LoopIndices(const rule::RuleContext& context);

}  // namespace shaderport::rules::webgl
