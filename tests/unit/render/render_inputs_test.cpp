// What the renderer feeds a shader: ShaderToy uniforms, channel textures of each
// kind or a user PNG, and a generated mesh with matrices for vertex shaders.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "render/isolated_render.h"
#include "render/png_io.h"
#include "render/render_checks.h"
#include "render/render_mesh.h"
#include "render_test_support.h"

namespace shaderport::render {
namespace {

using testing::FastOptions;
using testing::FragmentRequest;
using testing::ShaderToyText;

// Pixel (x, y) counted from the bottom, as GL reads it.
const float* At(const RenderOutcome& outcome, uint32_t x, uint32_t y) {
  return &outcome.pixels[(size_t{y} * outcome.width + x) * 4];
}

TEST(RenderInputs, ShaderToyUniformsAreDeterministicValues) {
  RenderRequest request = FragmentRequest(
      ShaderToyText("void mainImage(out vec4 c, in vec2 p) {\n"
                    "  c = vec4(iTime / 10.0, float(iFrame) / 10.0, iMouse.x / 100.0,\n"
                    "           iDate.w / 86400.0);\n}\n"),
      8);
  request.inputs.time = 2.0f;
  request.inputs.frame = 3;
  request.inputs.mouse = {25, 0, 0, 0};
  request.frames = 4;  // the last frame has iFrame 6 and iTime 2 + 3/60
  const RenderOutcome outcome = RenderIsolated(request, FastOptions());
  ASSERT_EQ(outcome.status, RenderStatus::kOk) << outcome.fragment_log;
  const float* p = At(outcome, 0, 0);
  EXPECT_NEAR(p[0], (2.0f + 3.0f / 60.0f) / 10.0f, 1e-6f);
  EXPECT_NEAR(p[1], 0.6f, 1e-6f);
  EXPECT_NEAR(p[2], 0.25f, 1e-6f);
  EXPECT_FLOAT_EQ(p[3], 1.0f);  // Image passes force alpha to 1
}

// The draw blends with GL's default factors (ONE, ZERO) so that llvmpipe compiles one
// fragment function instead of two; the colour written must still be the shader's own
// bits: negative zero, a denormal, a NaN with a payload, an infinity.
TEST(RenderInputs, FloatOutputBitsPassThroughTheBlend) {
  const std::string text =
      "#version 300 es\nprecision highp float;\nout vec4 o;\n"
      "void main() {\n  o = vec4(uintBitsToFloat(0x80000000u), uintBitsToFloat(1u),\n"
      "           uintBitsToFloat(0x7fc00123u), uintBitsToFloat(0xff800000u));\n}\n";
  const RenderOutcome outcome = RenderIsolated(FragmentRequest(text, 8), FastOptions());
  ASSERT_EQ(outcome.status, RenderStatus::kOk) << outcome.fragment_log;
  std::array<uint32_t, 4> bits{};
  std::memcpy(bits.data(), At(outcome, 3, 5), sizeof(bits));
  EXPECT_EQ(bits, (std::array<uint32_t, 4>{0x80000000u, 1u, 0x7fc00123u, 0xff800000u}));
}

TEST(RenderInputs, ProceduralChannelsOfEveryKindAreVaried) {
  const std::string text =
      "#version 300 es\nprecision highp float;\n"
      "uniform samplerCube iChannel0;\nuniform highp sampler3D iChannel1;\n"
      "uniform sampler2D iChannel2;\nuniform vec3 iChannelResolution[4];\n"
      "uniform vec3 iResolution;\nout vec4 o;\n"
      "void main() {\n  vec2 uv = gl_FragCoord.xy / iResolution.xy;\n"
      "  vec3 d = normalize(vec3(uv * 2.0 - 1.0, 0.6) * vec3(1.0, 1.0, uv.x - 0.5));\n"
      "  o = vec4(texture(iChannel0, d).r, texture(iChannel1, vec3(uv, 0.3)).g,\n"
      "           texture(iChannel2, uv).b * iChannelResolution[2].x / 256.0, 1.0);\n}\n";
  const RenderOutcome outcome = RenderIsolated(FragmentRequest(text), FastOptions());
  ASSERT_EQ(outcome.status, RenderStatus::kOk) << outcome.fragment_log;
  EXPECT_TRUE(CheckOutcome(outcome, {}).empty());
  EXPECT_NE(At(outcome, 2, 2)[0], At(outcome, 60, 60)[0]);  // cube faces differ
  EXPECT_NE(At(outcome, 2, 2)[1], At(outcome, 3, 40)[1]);   // 3D noise varies
}

TEST(RenderInputs, UserPngIsChannelZeroUpright) {
  ImageRgba8 image;  // 2x2: top row red, bottom row blue
  image.width = 2;
  image.height = 2;
  image.pixels = {255, 0, 0, 255, 255, 0, 0, 255, 0, 0, 255, 255, 0, 0, 255, 255};
  const std::string path = ::testing::TempDir() + "/render-channel0.png";
  const std::string png = EncodePng(image);
  ASSERT_FALSE(png.empty());
  std::ofstream(path, std::ios::binary) << png;
  std::string error;
  RenderRequest request = FragmentRequest(
      ShaderToyText("void mainImage(out vec4 c, in vec2 p) {\n"
                    "  c = texelFetch(iChannel0, ivec2(p / iResolution.xy * 2.0), 0);\n}\n"),
      8);
  ASSERT_TRUE(ReadPng(path, request.inputs.channels[0].image, error)) << error;
  const RenderOutcome outcome = RenderIsolated(request, FastOptions());
  ASSERT_EQ(outcome.status, RenderStatus::kOk) << outcome.fragment_log;
  EXPECT_FLOAT_EQ(At(outcome, 1, 7)[0], 1.0f);  // top of the picture: red
  EXPECT_FLOAT_EQ(At(outcome, 1, 0)[2], 1.0f);  // bottom: blue
}

TEST(RenderInputs, VertexShaderIsDrawnOnTheMeshWithMatrices) {
  RenderRequest request;
  request.vertex_source =
      "#version 300 es\n"
      "in vec3 Vertex;\nin vec3 Normal;\n"
      "uniform mat4 ProjectionMatrix;\nuniform mat4 ViewMatrix;\nuniform mat4 ModelMatrix;\n"
      "uniform vec3 ModelScale;\nout vec3 vNormal;\n"
      "void main() {\n"
      "  vNormal = Normal;\n"
      "  gl_Position = ProjectionMatrix * ViewMatrix * ModelMatrix * vec4(Vertex * ModelScale * "
      "2.0, 1.0);\n}\n";
  const RenderOutcome vertex_only = RenderIsolated(request, FastOptions());
  ASSERT_EQ(vertex_only.status, RenderStatus::kOk) << vertex_only.vertex_log;
  // The sphere (radius 1 after 0.5 * 2 scaling) is 3 units in front of the camera:
  // it covers the centre but not the corners.
  EXPECT_NE(At(vertex_only, 32, 32)[0], kSentinel[0]);
  EXPECT_EQ(At(vertex_only, 0, 0)[0], kSentinel[0]);
  CheckContext mesh;
  mesh.expect_full_coverage = false;
  EXPECT_TRUE(CheckOutcome(vertex_only, mesh).empty());

  // A vertex/fragment pair, linked through the varying.
  request.fragment_source =
      "#version 300 es\nprecision highp float;\nin vec3 vNormal;\nout vec4 o;\n"
      "void main() { o = vec4(vNormal * 0.5 + 0.5, 1.0); }\n";
  const RenderOutcome pair = RenderIsolated(request, FastOptions());
  ASSERT_EQ(pair.status, RenderStatus::kOk) << pair.link_log;
  EXPECT_NEAR(At(pair, 32, 32)[2], 1.0f, 0.1f);  // facing the camera: normal z near 1
}

TEST(RenderInputs, MismatchedVaryingIsALinkError) {
  RenderRequest request;
  request.vertex_source =
      "#version 300 es\nin vec3 Vertex;\nout vec2 v;\n"
      "void main() { v = Vertex.xy; gl_Position = vec4(Vertex, 1.0); }\n";
  request.fragment_source =
      "#version 300 es\nprecision highp float;\nin vec3 v;\nout vec4 o;\n"
      "void main() { o = vec4(v, 1.0); }\n";
  const RenderOutcome outcome = RenderIsolated(request, FastOptions());
  ASSERT_EQ(outcome.status, RenderStatus::kLinkFailed);
  EXPECT_EQ(CheckOutcome(outcome, {}).at(0).rule_id, "render/link-error");
}

TEST(RenderMesh, AttributesAreBoundByName) {
  EXPECT_EQ(StreamForAttribute("aNormal"), AttributeStream::kNormal);
  EXPECT_EQ(StreamForAttribute("TexCoord0"), AttributeStream::kTexCoord);
  EXPECT_EQ(StreamForAttribute("a_uv"), AttributeStream::kTexCoord);
  EXPECT_EQ(StreamForAttribute("vertexColor"), AttributeStream::kColor);
  EXPECT_EQ(StreamForAttribute("Vertex"), AttributeStream::kPosition);
  const SphereMesh mesh = MakeSphereMesh(8, 4);
  EXPECT_EQ(mesh.positions.size(), 9u * 5u * 4u);
  EXPECT_EQ(mesh.indices.size(), 8u * 4u * 6u);
}

}  // namespace
}  // namespace shaderport::render

namespace shaderport::render {
namespace {

TEST(RenderMultipass, BuffersPingPongAcrossFramesAndFeedTheImage) {
  // Buffer A adds 0.25 to its previous frame; Buffer B copies A of this frame and
  // halves it; Image shows A in red and B in green.
  RenderRequest request = testing::FragmentRequest(testing::ShaderToyText(
      "void mainImage(out vec4 c, in vec2 p) {\n"
      "  c = vec4(texelFetch(iChannel0, ivec2(p), 0).r, texelFetch(iChannel1, ivec2(p), 0).g,\n"
      "           p.x / iResolution.x, 1.0);\n}\n"));
  request.buffer_passes = {
      testing::BufferPassReading(0, 0,
                                 "void mainImage(out vec4 c, in vec2 p) {\n"
                                 "  c = texelFetch(iChannel0, ivec2(p), 0) + vec4(0.25);\n}\n"),
      testing::BufferPassReading(
          1, 0,
          "void mainImage(out vec4 c, in vec2 p) {\n"
          "  c = vec4(0.0, texelFetch(iChannel0, ivec2(p), 0).r * 0.5, 0.0, 1.0);\n}\n")};
  request.channel_buffers = {0, 1, -1, -1};
  request.frames = 3;
  const RenderOutcome outcome = RenderIsolated(request, testing::FastOptions());
  ASSERT_EQ(outcome.status, RenderStatus::kOk) << outcome.fragment_log;
  EXPECT_FLOAT_EQ(outcome.pixels[0], 0.75f);   // A after three frames
  EXPECT_FLOAT_EQ(outcome.pixels[1], 0.375f);  // B read A of the same frame
  EXPECT_TRUE(CheckOutcome(outcome, {}).empty());
}

TEST(RenderMultipass, CompileErrorNamesTheBufferPass) {
  RenderRequest request = testing::FragmentRequest(
      testing::ShaderToyText("void mainImage(out vec4 c, in vec2 p) { c = vec4(p, 0, 1); }\n"));
  BufferPass broken;
  broken.fragment_source =
      testing::ShaderToyText("void mainImage(out vec4 c, in vec2 p) { c = 1.0; }\n");
  request.buffer_passes = {broken};
  const RenderOutcome outcome = RenderIsolated(request, testing::FastOptions());
  ASSERT_EQ(outcome.status, RenderStatus::kCompileFailed);
  EXPECT_EQ(outcome.failed_pass, 0);
  CheckContext context;
  int mapped_pass = -1;
  context.map_buffer_line = [&](int pass, uint32_t) -> std::optional<SourceRange> {
    mapped_pass = pass;
    return std::nullopt;
  };
  const DiagnosticList found = CheckOutcome(outcome, context);
  ASSERT_FALSE(found.empty());
  EXPECT_EQ(mapped_pass, 0);
  EXPECT_NE(found[0].message.find("buffer pass 0"), std::string::npos) << found[0].message;
}

}  // namespace
}  // namespace shaderport::render
