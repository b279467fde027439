#include "render/gl_functions.h"

namespace shaderport::render {

bool LoadGlFunctions(GetProcFunction get_proc, GlFunctions& gl, std::string& missing) {
#define SHADERPORT_GL_LOAD(type, name)                    \
  gl.name = reinterpret_cast<type>(get_proc("gl" #name)); \
  if (gl.name == nullptr) {                               \
    missing = "gl" #name;                                 \
    return false;                                         \
  }
  SHADERPORT_GL_FUNCTIONS(SHADERPORT_GL_LOAD)
#undef SHADERPORT_GL_LOAD
  return true;
}

const char* GlErrorName(GLenum error) {
  switch (error) {
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    default:
      return "GL error";
  }
}

}  // namespace shaderport::render
