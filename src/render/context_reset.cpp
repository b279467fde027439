#include "render/context_reset.h"

#include <vector>

#include "render/uniform_values.h"

namespace shaderport::render {
namespace {

constexpr GLuint kMaxSweptNames = 1 << 16;  // far above what one render creates

// Every glGen*/glDelete* pair has these signatures.
using Generate = void(APIENTRYP)(GLsizei, GLuint*);
using Delete = void(APIENTRYP)(GLsizei, const GLuint*);

// Names 1..n, where n is the next free name (`next`, just generated).
std::vector<GLuint> NamesUpTo(GLuint next) {
  std::vector<GLuint> names;
  for (GLuint name = 1; name <= next && name <= kMaxSweptNames; ++name) names.push_back(name);
  return names;
}

void Sweep(const GlFunctions& gl, Generate GlFunctions::*generate, Delete GlFunctions::*erase) {
  GLuint next = 0;
  (gl.*generate)(1, &next);
  const std::vector<GLuint> names = NamesUpTo(next);
  (gl.*erase)(static_cast<GLsizei>(names.size()), names.data());
}

void DeleteObjects(const GlFunctions& gl) {
  Sweep(gl, &GlFunctions::GenTextures, &GlFunctions::DeleteTextures);
  Sweep(gl, &GlFunctions::GenSamplers, &GlFunctions::DeleteSamplers);
  Sweep(gl, &GlFunctions::GenFramebuffers, &GlFunctions::DeleteFramebuffers);
  Sweep(gl, &GlFunctions::GenRenderbuffers, &GlFunctions::DeleteRenderbuffers);
  Sweep(gl, &GlFunctions::GenBuffers, &GlFunctions::DeleteBuffers);
  Sweep(gl, &GlFunctions::GenVertexArrays, &GlFunctions::DeleteVertexArrays);
  // Programs and shaders share one namespace; deleting the wrong kind is an error.
  for (const GLuint name : NamesUpTo(gl.CreateShader(GL_FRAGMENT_SHADER))) {
    if (gl.IsProgram(name) == GL_TRUE) {
      gl.DeleteProgram(name);
    } else if (gl.IsShader(name) == GL_TRUE) {
      gl.DeleteShader(name);
    }
  }
}

}  // namespace

bool ResetContext(const GlFunctions& gl) {
  // Unbound first: a program in use, or a texture still attached, outlives its
  // deletion.
  gl.UseProgram(0);
  gl.BindVertexArray(0);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl.BindRenderbuffer(GL_RENDERBUFFER, 0);
  gl.BindBuffer(GL_ARRAY_BUFFER, 0);
  for (GLuint unit = 0; unit < static_cast<GLuint>(kMaxTextureUnits); ++unit) {
    gl.ActiveTexture(GL_TEXTURE0 + unit);
    for (const GLenum target : {GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP}) {
      gl.BindTexture(target, 0);
    }
    gl.BindSampler(unit, 0);
  }
  gl.ActiveTexture(GL_TEXTURE0);
  DeleteObjects(gl);
  gl.Disable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.Disable(GL_BLEND);
  gl.ClearColor(0, 0, 0, 0);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  gl.Finish();
  bool clean = true;
  for (int i = 0; i < 32 && gl.GetError() != GL_NO_ERROR; ++i) clean = false;
  return clean;
}

}  // namespace shaderport::render
