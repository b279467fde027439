// Returns a GL context to the state of a new one after a render, so that the render
// worker can keep one context for many renders and each picture is still the one a
// fresh context would draw.
#pragma once

#include "render/gl_functions.h"

namespace shaderport::render {

// Deletes every object name up to the next free one of each kind (a render deletes
// nothing, so its names are a run from 1) and sets back what a render changes: the
// bound program, vertex array, framebuffer, textures and samplers of every unit,
// depth test, clear colour and pixel alignments. False when GL still reports an
// error afterwards: the caller then drops the context instead of reusing it.
bool ResetContext(const GlFunctions& gl);

}  // namespace shaderport::render
