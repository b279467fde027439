#include "render/gl_program.h"

#include <algorithm>

namespace shaderport::render {
namespace {

template <typename GetLength, typename GetLog>
std::string ReadLog(GLuint object, GetLength get_length, GetLog get_log) {
  GLint length = 0;
  get_length(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
  get_log(object, std::max(length, 1), nullptr, log.data());
  log.resize(std::min(log.find('\0'), log.size()));
  return log;
}

bool Compile(const GlFunctions& gl, GLenum stage, const std::string& text, GLuint& shader,
             std::string& log) {
  shader = gl.CreateShader(stage);
  const char* source = text.c_str();
  const auto length = static_cast<GLint>(text.size());
  gl.ShaderSource(shader, 1, &source, &length);
  gl.CompileShader(shader);
  GLint ok = 0;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  log = ReadLog(shader, gl.GetShaderiv, gl.GetShaderInfoLog);
  return ok != 0;
}

}  // namespace

GLuint BuildProgram(const GlFunctions& gl, const std::string& vertex_text,
                    const std::string& fragment_text, RenderOutcome& outcome) {
  GLuint vertex = 0;
  GLuint fragment = 0;
  const bool vertex_ok = Compile(gl, GL_VERTEX_SHADER, vertex_text, vertex, outcome.vertex_log);
  const bool fragment_ok =
      Compile(gl, GL_FRAGMENT_SHADER, fragment_text, fragment, outcome.fragment_log);
  if (!vertex_ok || !fragment_ok) {
    outcome.status = RenderStatus::kCompileFailed;
    return 0;
  }
  const GLuint program = gl.CreateProgram();
  gl.AttachShader(program, vertex);
  gl.AttachShader(program, fragment);
  gl.LinkProgram(program);
  GLint linked = 0;
  gl.GetProgramiv(program, GL_LINK_STATUS, &linked);
  outcome.link_log = ReadLog(program, gl.GetProgramiv, gl.GetProgramInfoLog);
  if (!linked) {
    outcome.status = RenderStatus::kLinkFailed;
    return 0;
  }
  return program;
}

void CollectGlErrors(const GlFunctions& gl, const char* step, RenderOutcome& outcome) {
  for (int i = 0; i < 8; ++i) {  // GL keeps one flag per error kind; a few is all there is
    const GLenum error = gl.GetError();
    if (error == GL_NO_ERROR) return;
    outcome.gl_errors.push_back(std::string(GlErrorName(error)) + " after " + step);
  }
}

bool CreateFloatTarget(const GlFunctions& gl, GLsizei width, GLsizei height, bool depth,
                       FloatTarget& target) {
  gl.GenFramebuffers(1, &target.framebuffer);
  gl.BindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  gl.GenTextures(1, &target.texture);
  gl.BindTexture(GL_TEXTURE_2D, target.texture);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
  // Linear and clamped, as ShaderToy samples its buffers by default.
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.texture, 0);
  if (depth) {
    GLuint renderbuffer = 0;
    gl.GenRenderbuffers(1, &renderbuffer);
    gl.BindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, renderbuffer);
  }
  gl.BindTexture(GL_TEXTURE_2D, 0);
  return gl.CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

}  // namespace shaderport::render
