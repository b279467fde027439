// Shared helpers for the render tests: a ShaderToy-style composition (the real one
// lives in src/validate, which this layer does not link) and fast render options.
#pragma once

#include <string>

#include "render/isolated_render.h"
#include "render/render_request.h"

namespace shaderport::render::testing {

// A ShaderToy pass whose picture varies over x, y and iTime.
inline constexpr const char* kGradient =
    "void mainImage(out vec4 c, in vec2 p) {\n"
    "  vec2 uv = p / iResolution.xy;\n"
    "  c = vec4(uv, 0.5 + 0.5 * sin(iTime), 1.0);\n"
    "}\n";

// The site's header and main() around a mainImage body, as the driver composes it.
inline std::string ShaderToyText(const std::string& body) {
  return "#version 300 es\n"
         "precision highp float;\nprecision highp int;\nprecision mediump sampler3D;\n"
         "uniform vec3 iResolution;\nuniform float iTime;\nuniform float iChannelTime[4];\n"
         "uniform vec4 iMouse;\nuniform vec4 iDate;\nuniform float iSampleRate;\n"
         "uniform vec3 iChannelResolution[4];\nuniform int iFrame;\nuniform float iTimeDelta;\n"
         "uniform float iFrameRate;\n"
         "uniform sampler2D iChannel0;\nuniform sampler2D iChannel1;\n"
         "uniform sampler2D iChannel2;\nuniform sampler2D iChannel3;\n"
         "out vec4 shadertoy_out_color;\n#define HW_PERFORMANCE 1\n" +
         body +
         "\nvoid main() {\n  vec4 shadertoy_color = vec4(1e20);\n"
         "  mainImage(shadertoy_color, gl_FragCoord.xy);\n"
         "  shadertoy_out_color = vec4(shadertoy_color.xyz, 1.0);\n}\n";
}

inline RenderOptions FastOptions() {
  RenderOptions options;
  options.timeout = std::chrono::milliseconds(10'000);
  options.hermetic = true;  // tests must not depend on (or fill) a user's cache
  return options;
}

inline RenderRequest FragmentRequest(const std::string& fragment, uint32_t size = 64) {
  RenderRequest request;
  request.fragment_source = fragment;
  request.width = size;
  request.height = size;
  return request;
}

// A ShaderToy buffer pass writing `buffer` whose channel 0 reads buffer `reads`.
inline BufferPass BufferPassReading(int buffer, int reads, const std::string& main_image) {
  BufferPass pass;
  pass.buffer = buffer;
  pass.channel_buffers = {reads, -1, -1, -1};
  pass.fragment_source = ShaderToyText(main_image);
  return pass;
}

}  // namespace shaderport::render::testing
