// When a channel's sampler type explains glslang's errors: a channel taken as 2D
// but sampled with a 3-component coordinate (or taken as a cube map and sampled
// with a 2-component one) makes glslang report a missing overload and the
// assignments after it. Each such error gets a note naming the channel, its type,
// where the type came from, and the option that changes it.
#pragma once

#include "diag/diagnostic.h"
#include "driver/file_decision.h"
#include "driver/front_end.h"

namespace shaderport::driver {

void ExplainChannelErrors(const FrontEndResult& front, const FileDecision& decision,
                          DiagnosticList& diagnostics);

}  // namespace shaderport::driver
