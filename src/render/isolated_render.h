// Every render runs in a child process forked before any GL context exists, with a
// wall-clock timeout and an address-space limit; the result comes back through a
// pipe. A shader that hangs llvmpipe (there is no way to abort glDrawArrays) is
// killed, and the parent never holds GL state or driver threads.
#pragma once

#include "render/render_request.h"

namespace shaderport::render {

// Never throws and never leaves a process behind. Status kTimeout / kCrashed when
// the child was killed or died; kOk with pixels otherwise.
RenderOutcome RenderIsolated(const RenderRequest& request, const RenderOptions& options);

// $XDG_CACHE_HOME/shaderport/mesa, or ~/.cache/shaderport/mesa.
std::string DefaultMesaCacheDir();

}  // namespace shaderport::render
