// Compiling and linking a vertex/fragment pair, keeping Mesa's logs for the checks.
#pragma once

#include <string>

#include "render/gl_functions.h"
#include "render/render_request.h"

namespace shaderport::render {

// 0 on failure, with the status and logs stored in `outcome`.
GLuint BuildProgram(const GlFunctions& gl, const std::string& vertex_text,
                    const std::string& fragment_text, RenderOutcome& outcome);

// Records glGetError flags as "GL_X after `step`".
void CollectGlErrors(const GlFunctions& gl, const char* step, RenderOutcome& outcome);

// An RGBA32F texture with a framebuffer object (and a depth buffer when asked).
struct FloatTarget {
  GLuint framebuffer = 0;
  GLuint texture = 0;
};
bool CreateFloatTarget(const GlFunctions& gl, GLsizei width, GLsizei height, bool depth,
                       FloatTarget& target);

}  // namespace shaderport::render
