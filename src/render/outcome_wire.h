// The byte format a render child writes to its pipe: a flat encoding of
// RenderOutcome. The parent treats a short or malformed message as a crash.
#pragma once

#include <optional>
#include <string>

#include "render/render_request.h"

namespace shaderport::render {

std::string EncodeOutcome(const RenderOutcome& outcome);
std::optional<RenderOutcome> DecodeOutcome(const std::string& bytes);

}  // namespace shaderport::render
