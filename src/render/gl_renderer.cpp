#include "render/gl_renderer.h"

#include <algorithm>
#include <array>
#include <memory>

#include "render/builtin_shaders.h"
#include "render/gl_program.h"
#include "render/loop_cap.h"
#include "render/render_mesh.h"
#include "render/uniform_values.h"

namespace shaderport::render {

namespace {

// Ping-pong pairs for the ShaderToy buffers A..D that the request uses.
struct BufferTargets {
  std::array<std::array<FloatTarget, 2>, 4> targets{};
  std::array<int, 4> latest = {0, 0, 0, 0};
  std::array<bool, 4> used{};
  // Read with a mipmap filter somewhere: mipmaps are rebuilt after each write, as
  // the site and the project page do.
  std::array<bool, 4> mipmapped{};
};

// The buffer each channel reads: the pass's own channels when the request gives
// them, else `channel_buffers`.
std::array<int, 4> BuffersRead(const PassChannels& channels,
                               const std::array<int, 4>& channel_buffers) {
  std::array<int, 4> read = channel_buffers;
  for (size_t i = 0; i < 4; ++i) {
    if (channels[i].kind == PassChannelKind::kFromInputs) continue;
    read[i] = channels[i].kind == PassChannelKind::kBuffer ? channels[i].buffer : -1;
  }
  return read;
}

// A project's passes read buffers that no pass writes too: those are zero on the
// site, so they get (cleared) targets as well.
void NoteBuffersRead(const PassChannels& channels, BufferTargets& buffers) {
  for (const PassChannel& channel : channels) {
    if (channel.kind != PassChannelKind::kBuffer || channel.buffer < 0 || channel.buffer > 3)
      continue;
    const auto k = static_cast<size_t>(channel.buffer);
    buffers.used[k] = true;
    if (channel.filter == ChannelFilter::kMipmap) buffers.mipmapped[k] = true;
  }
}

void BuildMipmaps(const GlFunctions& gl, GLuint texture) {
  gl.BindTexture(GL_TEXTURE_2D, texture);
  gl.GenerateMipmap(GL_TEXTURE_2D);
  gl.BindTexture(GL_TEXTURE_2D, 0);
}

ChannelOverrides OverridesFor(const PassChannels& channels,
                              const std::array<int, 4>& channel_buffers,
                              const BufferTargets& buffers, const RenderRequest& request) {
  ChannelOverrides overrides{};
  const std::array<int, 4> read = BuffersRead(channels, channel_buffers);
  for (size_t i = 0; i < 4; ++i) {
    const int k = read[i];
    if (k < 0 || k > 3 || !buffers.used[static_cast<size_t>(k)]) continue;
    const auto& pair = buffers.targets[static_cast<size_t>(k)];
    overrides[i] = {pair[static_cast<size_t>(buffers.latest[static_cast<size_t>(k)])].texture,
                    static_cast<float>(request.width), static_cast<float>(request.height)};
  }
  return overrides;
}

// A second colour attachment for the render probe, when the program writes one at
// location 1 (see RenderRequest::probe_output). Two channels are all that is read
// (.z only keeps conditions exact in Mesa's compiler); llvmpipe's code for storing
// each channel is compiled with every shader.
GLuint AttachProbe(const GlFunctions& gl, GLuint program, const RenderRequest& request,
                   GLsizei width, GLsizei height) {
  if (request.probe_output.empty() ||
      gl.GetFragDataLocation(program, request.probe_output.c_str()) != 1) {
    return 0;
  }
  GLuint texture = 0;
  gl.GenTextures(1, &texture);
  gl.BindTexture(GL_TEXTURE_2D, texture);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, width, height, 0, GL_RG, GL_FLOAT, nullptr);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, texture, 0);
  gl.BindTexture(GL_TEXTURE_2D, 0);
  const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  gl.DrawBuffers(2, buffers);
  return texture;
}

void CountLoopIterations(float count, RenderOutcome& outcome) {
  if (!(count > 0.0f)) return;  // not written (the clear sentinel is negative) or NaN
  const auto iterations = static_cast<int64_t>(std::min(count, 1e12f));
  outcome.max_loop_iterations = std::max(outcome.max_loop_iterations, iterations);
  if (static_cast<uint64_t>(iterations) >= kLlvmpipeLoopCap) ++outcome.loop_capped_pixels;
}

void ReadProbe(const GlFunctions& gl, GLsizei width, GLsizei height, RenderOutcome& outcome) {
  std::vector<float> probe(static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
  gl.ReadBuffer(GL_COLOR_ATTACHMENT1);
  gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, probe.data());
  gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
  outcome.max_loop_iterations = 0;
  outcome.unassigned_output_pixels = 0;
  for (size_t i = 0; i < probe.size(); i += 4) {
    // .y: 1 where the colour output was assigned; the clear sentinel where the
    // fragment was discarded (not this check's business).
    if (probe[i + 1] == 0.0f) ++outcome.unassigned_output_pixels;
    CountLoopIterations(probe[i], outcome);
  }
}

// The probe in the colour's alpha (RenderRequest::probe_in_alpha): the count where
// the output was assigned, -1 - the count where it was not; alpha becomes 1 again.
// A discarded fragment left the clear sentinel, alpha included.
void ReadAlphaProbe(RenderOutcome& outcome) {
  outcome.max_loop_iterations = 0;
  outcome.unassigned_output_pixels = 0;
  for (size_t i = 0; i + 3 < outcome.pixels.size(); i += 4) {
    float* pixel = &outcome.pixels[i];
    if (std::equal(kSentinel.begin(), kSentinel.end(), pixel)) continue;
    const float alpha = pixel[3];
    pixel[3] = 1.0f;
    const bool assigned = alpha >= 0.0f;
    if (!assigned) ++outcome.unassigned_output_pixels;
    CountLoopIterations(assigned ? alpha : -1.0f - alpha, outcome);
  }
}

}  // namespace

RenderOutcome DrawRequest(const GlFunctions& gl, const RenderRequest& request) {
  RenderOutcome outcome;
  const bool user_vertex = !request.vertex_source.empty() && !request.fullscreen_vertex;
  const std::string vertex_text =
      request.vertex_source.empty() ? std::string(kFullScreenVertexShader) : request.vertex_source;
  const std::string fragment_text =
      request.fragment_source.empty() ? kFlatFragmentShader : request.fragment_source;
  std::vector<GLuint> buffer_programs;
  for (size_t p = 0; p < request.buffer_passes.size(); ++p) {
    const GLuint built = BuildProgram(gl, kFullScreenVertexShader,
                                      request.buffer_passes[p].fragment_source, outcome);
    if (built == 0) {
      outcome.failed_pass = static_cast<int>(p);
      return outcome;
    }
    buffer_programs.push_back(built);
  }
  const GLuint program = BuildProgram(gl, vertex_text, fragment_text, outcome);
  if (program == 0) return outcome;

  // Float colour targets, so NaN and out-of-range values survive to the checks.
  const auto width = static_cast<GLsizei>(request.width);
  const auto height = static_cast<GLsizei>(request.height);
  BufferTargets buffers;
  for (const BufferPass& pass : request.buffer_passes) {
    buffers.used[static_cast<size_t>(pass.buffer & 3)] = true;
    NoteBuffersRead(pass.channels, buffers);
  }
  NoteBuffersRead(request.channels, buffers);
  for (size_t k = 0; k < 4; ++k) {
    if (!buffers.used[k]) continue;
    for (FloatTarget& target : buffers.targets[k]) {
      if (!CreateFloatTarget(gl, width, height, false, target)) {
        outcome.status = RenderStatus::kContextFailed;
        outcome.message = "an RGBA32F buffer framebuffer is incomplete";
        return outcome;
      }
      gl.ClearColor(0, 0, 0, 0);  // the site starts buffers at zero
      gl.Clear(GL_COLOR_BUFFER_BIT);
      // Every level zero, so a mipmapped read of the first frame sees zeros.
      if (buffers.mipmapped[k]) BuildMipmaps(gl, target.texture);
    }
  }
  FloatTarget main_target;
  if (!CreateFloatTarget(gl, width, height, true, main_target)) {
    outcome.status = RenderStatus::kContextFailed;
    outcome.message = "the RGBA32F framebuffer is incomplete";
    return outcome;
  }
  const GLuint probe = AttachProbe(gl, program, request, width, height);
  CollectGlErrors(gl, "creating the framebuffers", outcome);

  GLuint vao = 0;
  gl.GenVertexArrays(1, &vao);
  gl.BindVertexArray(vao);
  MeshBuffers mesh;
  if (user_vertex) mesh = UploadMeshForProgram(gl, program, MakeSphereMesh(32, 16));
  CollectGlErrors(gl, "setting up the vertex inputs", outcome);
  gl.Viewport(0, 0, width, height);
  // Blending with GL's default factors (ONE, ZERO) writes the shader's bits unchanged
  // (-0, denormals, NaN payloads and infinities pass through; tested), and llvmpipe
  // then compiles one fragment function for a pass with a single colour target instead
  // of two (it adds a copy for whole blocks when a target is "opaque"). Passes with
  // the probe's second target compile once either way.
  gl.Enable(GL_BLEND);
  std::vector<ProgramTextures> buffer_textures(buffer_programs.size());
  ProgramTextures textures;
  const int frames = std::max(request.frames, 1);
  for (int frame = 0; frame < frames; ++frame) {
    gl.Disable(GL_DEPTH_TEST);
    for (size_t p = 0; p < buffer_programs.size(); ++p) {
      const BufferPass& pass = request.buffer_passes[p];
      const auto k = static_cast<size_t>(pass.buffer & 3);
      const int write = 1 - buffers.latest[k];
      gl.BindFramebuffer(GL_FRAMEBUFFER,
                         buffers.targets[k][static_cast<size_t>(write)].framebuffer);
      gl.UseProgram(buffer_programs[p]);
      SetUniforms(gl, buffer_programs[p], request, frame, buffer_textures[p], pass.channels,
                  OverridesFor(pass.channels, pass.channel_buffers, buffers, request));
      gl.DrawArrays(GL_TRIANGLES, 0, 3);
      CollectGlErrors(gl, "drawing a buffer pass", outcome);
      buffers.latest[k] = write;
      if (buffers.mipmapped[k])
        BuildMipmaps(gl, buffers.targets[k][static_cast<size_t>(write)].texture);
    }
    gl.BindFramebuffer(GL_FRAMEBUFFER, main_target.framebuffer);
    gl.UseProgram(program);
    SetUniforms(gl, program, request, frame, textures, request.channels,
                OverridesFor(request.channels, request.channel_buffers, buffers, request));
    CollectGlErrors(gl, "setting uniforms and textures", outcome);
    gl.ClearColor(kSentinel[0], kSentinel[1], kSentinel[2], kSentinel[3]);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (user_vertex) {
      gl.Enable(GL_DEPTH_TEST);
      gl.DepthFunc(GL_LESS);
      gl.DrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
      CollectGlErrors(gl, "glDrawElements", outcome);
    } else {
      gl.DrawArrays(GL_TRIANGLES, 0, 3);
      CollectGlErrors(gl, "glDrawArrays", outcome);
    }
  }
  gl.Finish();
  outcome.width = request.width;
  outcome.height = request.height;
  outcome.pixels.resize(size_t{request.width} * request.height * 4);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, outcome.pixels.data());
  if (probe != 0) ReadProbe(gl, width, height, outcome);
  if (request.probe_in_alpha) ReadAlphaProbe(outcome);
  CollectGlErrors(gl, "glReadPixels", outcome);
  outcome.status = RenderStatus::kOk;
  return outcome;  // the caller deletes what was made (ReusableContext)
}

}  // namespace shaderport::render
