#include "render/context_reset.h"

#include <vector>

namespace shaderport::render {
namespace {

constexpr GLuint kTextureUnits = 16;        // as many as SetUniforms binds
constexpr GLuint kMaxSweptNames = 1 << 16;  // far above what one render creates

// Names 1..n, where n is the next name `generate` hands out.
std::vector<GLuint> NamesInUse(const GlFunctions& gl,
                               void (*generate)(const GlFunctions&, GLuint&)) {
  GLuint next = 0;
  generate(gl, next);
  std::vector<GLuint> names;
  for (GLuint name = 1; name <= next && name <= kMaxSweptNames; ++name) names.push_back(name);
  return names;
}

GLsizei Count(const std::vector<GLuint>& names) { return static_cast<GLsizei>(names.size()); }

void DeleteObjects(const GlFunctions& gl) {
  auto names = NamesInUse(gl, [](const GlFunctions& f, GLuint& n) { f.GenTextures(1, &n); });
  gl.DeleteTextures(Count(names), names.data());
  names = NamesInUse(gl, [](const GlFunctions& f, GLuint& n) { f.GenSamplers(1, &n); });
  gl.DeleteSamplers(Count(names), names.data());
  names = NamesInUse(gl, [](const GlFunctions& f, GLuint& n) { f.GenFramebuffers(1, &n); });
  gl.DeleteFramebuffers(Count(names), names.data());
  names = NamesInUse(gl, [](const GlFunctions& f, GLuint& n) { f.GenRenderbuffers(1, &n); });
  gl.DeleteRenderbuffers(Count(names), names.data());
  names = NamesInUse(gl, [](const GlFunctions& f, GLuint& n) { f.GenBuffers(1, &n); });
  gl.DeleteBuffers(Count(names), names.data());
  names = NamesInUse(gl, [](const GlFunctions& f, GLuint& n) { f.GenVertexArrays(1, &n); });
  gl.DeleteVertexArrays(Count(names), names.data());
  // Programs and shaders share one namespace; deleting the wrong kind is an error.
  names = NamesInUse(
      gl, [](const GlFunctions& f, GLuint& n) { n = f.CreateShader(GL_FRAGMENT_SHADER); });
  for (const GLuint name : names) {
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
  for (GLuint unit = 0; unit < kTextureUnits; ++unit) {
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
  gl.ClearColor(0, 0, 0, 0);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  gl.Finish();
  bool clean = true;
  for (int i = 0; i < 32 && gl.GetError() != GL_NO_ERROR; ++i) clean = false;
  return clean;
}

}  // namespace shaderport::render
