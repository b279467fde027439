// What to draw and what came back. The request is plain data so that it can be
// handed to a forked child; the outcome is what the child sends back through a pipe.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "model/channel_kind.h"
#include "render/gl_backend.h"

namespace shaderport::render {

// 8-bit RGBA, rows top-down (as PNG stores them).
struct ImageRgba8 {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> pixels;  // width * height * 4
};

struct ChannelInput {
  model::ChannelKind kind = model::ChannelKind::k2D;
  ImageRgba8 image;  // used for k2D when non-empty, else a procedural texture
  // The site feeds nothing to this channel: no texture is bound, so sampling gives
  // (0, 0, 0, 1) and iChannelResolution is 0, as in the browser.
  bool unbound = false;
};

// Deterministic values for the ShaderToy uniforms (set only where the program has them).
struct ShaderToyInputs {
  float time = 1.0f;                                // iTime of the first frame
  int frame = 0;                                    // iFrame of the first frame
  float frame_rate = 60.0f;                         // frames advance iTime by 1/frame_rate
  std::array<float, 4> mouse = {0, 0, 0, 0};        // iMouse, pixels
  std::array<float, 4> date = {2025, 0, 1, 43200};  // iDate: fixed, so renders repeat
  std::array<ChannelInput, 4> channels;
};

// How a project's input is sampled: its `sampler.filter` and `sampler.wrap`.
enum class ChannelFilter : uint8_t { kMipmap, kLinear, kNearest };
enum class ChannelWrap : uint8_t { kRepeat, kClamp };

// What one channel of one pass of a ShaderToy project reads. The site binds each
// pass's own inputs, so every pass (the main one and each BufferPass) has its own.
// Not a model::ChannelKind: what is bound (a buffer, the keyboard, nothing), not how it samples.
enum class PassChannelKind : uint8_t {
  // Not given: the channel is bound as single-pass renders bind it, from
  // ShaderToyInputs::channels and the pass's channel_buffers.
  kFromInputs,
  kUnbound,   // nothing bound: samples (0, 0, 0, 1), iChannelResolution 0
  kTexture,   // texture, video, audio: the --channelN image or the procedural 2D texture
  kCube,      // cube map: the procedural cube
  kVolume,    // the procedural 3D noise
  kKeyboard,  // 256x3 R8 of zeros: no key is down in a headless render
  kBuffer,    // Buffer A..D (`buffer`)
};
inline constexpr uint8_t kLastPassChannelKind = static_cast<uint8_t>(PassChannelKind::kBuffer);

struct PassChannel {
  PassChannelKind kind = PassChannelKind::kFromInputs;
  int buffer = -1;  // kBuffer: 0..3
  ChannelFilter filter = ChannelFilter::kMipmap;
  ChannelWrap wrap = ChannelWrap::kRepeat;
  bool vflip = true;  // for a user image only (procedural textures are in GL order)
};
using PassChannels = std::array<PassChannel, 4>;

// A ShaderToy Buffer pass, drawn every frame before the main pass into a ping-pong
// pair of RGBA32F textures: a pass reading itself (or a later buffer) sees the
// previous frame, one reading an earlier buffer sees this frame, as on the site.
struct BufferPass {
  int buffer = 0;               // 0..3: Buffer A..D, the output it writes
  std::string fragment_source;  // complete text, drawn on the full-screen triangle
  std::array<int, 4> channel_buffers = {-1, -1, -1, -1};  // iChannelN reads buffer k, or -1
  PassChannels channels{};  // when given, these decide (channel_buffers is then unused)
};

struct RenderRequest {
  // Complete GLSL texts (`#version 300 es`). An empty vertex shader means the
  // built-in full-screen triangle; an empty fragment shader a built-in flat shader,
  // for smoke-testing a vertex shader on the generated mesh.
  std::string vertex_source;
  std::string fragment_source;
  // The vertex shader draws the full-screen triangle from gl_VertexID (e.g. one
  // written to feed a fragment shader's inputs) instead of the generated mesh.
  bool fullscreen_vertex = false;
  uint32_t width = 64;
  uint32_t height = 64;
  int frames = 1;  // frames drawn; the last one is read back
  ShaderToyInputs inputs;
  std::vector<BufferPass> buffer_passes;                  // ShaderToy multipass, in drawing order
  std::array<int, 4> channel_buffers = {-1, -1, -1, -1};  // the main pass's buffer inputs
  PassChannels channels{};  // the main pass's own channels, as BufferPass::channels
  // A fragment output (location 1) whose .x counts the loop iterations of each pixel
  // and whose .y is 1 where the colour output was assigned (added by the driver's
  // render text); empty or absent in the program: not read.
  std::string probe_output;
  // Instead, the colour output's alpha carries the probe: the count where the output
  // was assigned, -1 - the count where it was not. Read back, alpha is 1 again (the
  // ShaderToy Image pass's own alpha, which the probe replaced).
  bool probe_in_alpha = false;
};

struct RenderOptions {
  BackendKind backend = DefaultBackend();
  std::chrono::milliseconds timeout{10'000};
  uint64_t address_space_limit = uint64_t{4} << 30;  // RLIMIT_AS of the child; 0: none
  bool hermetic = false;                             // disable Mesa's shader cache
  std::string cache_dir;  // Mesa shader cache; empty: $XDG_CACHE_HOME/shaderport/mesa
};

enum class RenderStatus : uint8_t {
  kOk,
  kCompileFailed,
  kLinkFailed,
  kContextFailed,
  kTimeout,
  kCrashed,
  kInternal,
};

// The value the framebuffer is cleared to: a pixel still holding it was never written.
inline constexpr std::array<float, 4> kSentinel = {-7777.0f, 1234.5f, -4321.0f, 9876.5f};

struct RenderOutcome {
  RenderStatus status = RenderStatus::kInternal;
  std::string message;  // context failure, crash or timeout description
  std::string vertex_log;
  std::string fragment_log;
  std::string link_log;
  int failed_pass = -1;                // index in buffer_passes whose compile/link failed; -1: main
  std::vector<std::string> gl_errors;  // "GL_INVALID_OPERATION after glDrawArrays"
  // From the loop probe: the most loop iterations of any pixel (-1: not measured),
  // and how many pixels reached llvmpipe's cap.
  int64_t max_loop_iterations = -1;
  uint32_t loop_capped_pixels = 0;
  // Pixels whose probe says the colour output was never assigned (-1: not measured).
  int64_t unassigned_output_pixels = -1;
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> pixels;  // RGBA32F, rows bottom-up as glReadPixels returns them
  double milliseconds = 0;    // wall time of the whole render, child start to result
};

// Maximum render size per side; larger requests are clamped by the caller's checks.
inline constexpr uint32_t kMaxRenderSide = 4096;

}  // namespace shaderport::render
