// The byte format the parent writes to a render worker: a flat encoding of
// RenderRequest (outcome_wire.h is the way back). The worker treats a malformed
// request as fatal and exits, so the parent replaces it.
#pragma once

#include <optional>
#include <string>

#include "render/render_request.h"

namespace shaderport::render {

std::string EncodeRequest(const RenderRequest& request);
std::optional<RenderRequest> DecodeRequest(const std::string& bytes);

}  // namespace shaderport::render
