// Stable rule ids and readable texts for glslang's messages.
#pragma once

#include <string>
#include <string_view>

#include "validate/glslang_log.h"

namespace shaderport::validate {

// The rule id (listed in src/diag/catalog/glslang.def) for a message, chosen from
// its text: glslang's wording is stable within a major version, the ids are ours.
std::string_view ClassifyGlslangMessage(const GlslangMessage& message);

// glslang's message as shown to users: "'<token>': <text>", with runs of spaces
// collapsed and the storage words glslang prints inside quoted types removed
// ("' temp highp float'" -> "'highp float'", likewise "global"): they describe
// glslang's internal storage class, not anything the user wrote. `const` stays
// because it tells the user the value is a constant.
std::string TidyGlslangText(const GlslangMessage& message);

}  // namespace shaderport::validate
