// Draws a request with a fresh GL context in the calling process. Only the render
// child calls this (see isolated_render.h): a shader can hang the GL driver, and
// creating a context starts llvmpipe threads that must not exist before a fork.
#pragma once

#include "render/gl_functions.h"
#include "render/render_request.h"

namespace shaderport::render {

// The built-in shaders used when the request leaves a stage empty.
extern const char* const kFullScreenVertexShader;
extern const char* const kFlatFragmentShader;

// Draws `request` with the current context, whose state must be that of a new one.
RenderOutcome DrawRequest(const GlFunctions& gl, const RenderRequest& request);

// Draws a request with a fresh GL context (see ReusableContext for several).
RenderOutcome RenderInThisProcess(const RenderRequest& request, BackendKind backend);

}  // namespace shaderport::render
