#include "render/gl_renderer.h"

#include <algorithm>
#include <memory>

#include "render/render_mesh.h"
#include "render/uniform_values.h"

namespace shaderport::render {

// gl_VertexID 0, 1, 2 -> (-1,-1), (3,-1), (-1,3): one triangle covers the viewport.
const char* const kFullScreenVertexShader =
    "#version 300 es\n"
    "void main() {\n"
    "  vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);\n"
    "  gl_Position = vec4(p, 0.0, 1.0);\n"
    "}\n";

// Shades by depth, so that a vertex shader's geometry is visible.
const char* const kFlatFragmentShader =
    "#version 300 es\n"
    "precision highp float;\n"
    "out vec4 shaderport_color;\n"
    "void main() {\n"
    "  shaderport_color = vec4(vec3(0.9 - 0.8 * gl_FragCoord.z), 1.0);\n"
    "}\n";

namespace {

// A render process has one context; GetProcAddress needs a plain function.
GlBackend* current_backend = nullptr;
void* CurrentBackendProc(const char* name) { return current_backend->GetProc(name); }

std::string ShaderLog(const GlFunctions& gl, GLuint shader) {
  GLint length = 0;
  gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
  gl.GetShaderInfoLog(shader, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

std::string ProgramLog(const GlFunctions& gl, GLuint program) {
  GLint length = 0;
  gl.GetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
  gl.GetProgramInfoLog(program, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
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
  log = ShaderLog(gl, shader);
  return ok != 0;
}

void CollectErrors(const GlFunctions& gl, const char* step, RenderOutcome& outcome) {
  for (int i = 0; i < 8; ++i) {  // GL keeps one flag per error kind; a few is all there is
    const GLenum error = gl.GetError();
    if (error == GL_NO_ERROR) return;
    outcome.gl_errors.push_back(std::string(GlErrorName(error)) + " after " + step);
  }
}

}  // namespace

RenderOutcome RenderInThisProcess(const RenderRequest& request, BackendKind backend_kind) {
  RenderOutcome outcome;
  std::unique_ptr<GlBackend> backend = CreateBackend(backend_kind);
  std::string error;
  if (!backend->Start(error)) {
    outcome.status = RenderStatus::kContextFailed;
    outcome.message = std::string(BackendName(backend_kind)) + ": " + error;
    return outcome;
  }
  GlFunctions gl;
  std::string missing;
  current_backend = backend.get();
  if (!LoadGlFunctions(&CurrentBackendProc, gl, missing)) {
    outcome.status = RenderStatus::kContextFailed;
    outcome.message = std::string(BackendName(backend_kind)) + ": no entry point " + missing;
    return outcome;
  }

  const bool user_vertex = !request.vertex_source.empty();
  const std::string vertex_text = user_vertex ? request.vertex_source : kFullScreenVertexShader;
  const std::string fragment_text =
      request.fragment_source.empty() ? kFlatFragmentShader : request.fragment_source;
  GLuint vertex = 0;
  GLuint fragment = 0;
  const bool vertex_ok = Compile(gl, GL_VERTEX_SHADER, vertex_text, vertex, outcome.vertex_log);
  const bool fragment_ok =
      Compile(gl, GL_FRAGMENT_SHADER, fragment_text, fragment, outcome.fragment_log);
  if (!vertex_ok || !fragment_ok) {
    outcome.status = RenderStatus::kCompileFailed;
    return outcome;
  }
  const GLuint program = gl.CreateProgram();
  gl.AttachShader(program, vertex);
  gl.AttachShader(program, fragment);
  gl.LinkProgram(program);
  GLint linked = 0;
  gl.GetProgramiv(program, GL_LINK_STATUS, &linked);
  outcome.link_log = ProgramLog(gl, program);
  if (!linked) {
    outcome.status = RenderStatus::kLinkFailed;
    return outcome;
  }

  // Float colour target, so NaN and out-of-range values survive to the checks.
  const auto width = static_cast<GLsizei>(request.width);
  const auto height = static_cast<GLsizei>(request.height);
  GLuint framebuffer = 0;
  GLuint color = 0;
  GLuint depth = 0;
  gl.GenFramebuffers(1, &framebuffer);
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  gl.GenTextures(1, &color);
  gl.BindTexture(GL_TEXTURE_2D, color);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
  gl.GenRenderbuffers(1, &depth);
  gl.BindRenderbuffer(GL_RENDERBUFFER, depth);
  gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  gl.BindTexture(GL_TEXTURE_2D, 0);
  if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    outcome.status = RenderStatus::kContextFailed;
    outcome.message = "the RGBA32F framebuffer is incomplete";
    return outcome;
  }
  CollectErrors(gl, "creating the framebuffer", outcome);

  GLuint vao = 0;
  gl.GenVertexArrays(1, &vao);
  gl.BindVertexArray(vao);
  gl.UseProgram(program);
  MeshBuffers mesh;
  if (user_vertex) {
    mesh = UploadMeshForProgram(gl, program, MakeSphereMesh(32, 16));
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
  }
  CollectErrors(gl, "setting up the vertex inputs", outcome);
  gl.Viewport(0, 0, width, height);
  std::vector<GLuint> textures;
  const int frames = std::max(request.frames, 1);
  for (int frame = 0; frame < frames; ++frame) {
    SetUniforms(gl, program, request, frame, textures);
    CollectErrors(gl, "setting uniforms and textures", outcome);
    gl.ClearColor(kSentinel[0], kSentinel[1], kSentinel[2], kSentinel[3]);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (user_vertex) {
      gl.DrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
      CollectErrors(gl, "glDrawElements", outcome);
    } else {
      gl.DrawArrays(GL_TRIANGLES, 0, 3);
      CollectErrors(gl, "glDrawArrays", outcome);
    }
  }
  gl.Finish();
  outcome.width = request.width;
  outcome.height = request.height;
  outcome.pixels.resize(size_t{request.width} * request.height * 4);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, outcome.pixels.data());
  CollectErrors(gl, "glReadPixels", outcome);
  outcome.status = RenderStatus::kOk;
  // The process exits right after: GL objects die with the context.
  return outcome;
}

}  // namespace shaderport::render
