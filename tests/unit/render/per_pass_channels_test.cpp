// ShaderToy projects bind each pass's own channels, sampled as each input's
// `sampler` says (docs/render.md "Per-pass channels"): what shadertoy.com and the
// project page do. Drawn through the binary (skipped when it is not built).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "render/png_io.h"
#include "render/request_wire.h"

namespace shaderport::render {
namespace {

using nlohmann::json;

class PerPassChannels : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(SHADERPORT_BINARY)) GTEST_SKIP() << "shaderport not built";
  }

  // Renders an Image pass and an optional Buffer A at 8x8, one frame.
  static ImageRgba8 Render(const std::string& name, const std::string& image_code,
                           const json& image_inputs, const std::string& buffer_code = "",
                           const json& buffer_inputs = json::array()) {
    json passes = json::array(
        {{{"type", "image"}, {"name", "Image"}, {"code", image_code}, {"inputs", image_inputs}}});
    if (!buffer_code.empty()) {
      passes.push_back({{"type", "buffer"},
                        {"name", "Buffer A"},
                        {"code", buffer_code},
                        {"inputs", buffer_inputs}});
    }
    const std::string base = ::testing::TempDir() + "/per-pass-" + name;
    std::ofstream(base + ".json") << json{{"passes", passes}}.dump();
    const std::string command = std::string(SHADERPORT_BINARY) + " render --hermetic --size 8x8 " +
                                base + ".json -o " + base + ".png 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    std::string output;
    char chunk[4096];
    for (size_t n = 0; pipe != nullptr && (n = fread(chunk, 1, sizeof(chunk), pipe)) > 0;)
      output.append(chunk, n);
    if (pipe != nullptr) pclose(pipe);
    ImageRgba8 image;
    std::string error;
    EXPECT_TRUE(ReadPng(base + ".png", image, error)) << error << output;
    return image;
  }
};

json Input(int channel, const std::string& ctype, const std::string& src,
           const std::string& filter = "mipmap", const std::string& wrap = "repeat") {
  return {{"channel", channel},
          {"ctype", ctype},
          {"src", src},
          {"sampler", {{"filter", filter}, {"wrap", wrap}, {"vflip", "true"}}}};
}

const char* const kBufferA = "/media/previz/buffer00.png";

// Pixel (x, y) of a PNG (top row first), channel c.
int At(const ImageRgba8& image, uint32_t x, uint32_t y, int c) {
  return image.pixels[(size_t{y} * image.width + x) * 4 + static_cast<size_t>(c)];
}

// Buffer A samples a texture on iChannel1, which the Image pass leaves unbound: the
// buffer pass still gets its texture (texel (0, 0) of the procedural 2D texture has
// blue 200) and its iChannelResolution.
TEST_F(PerPassChannels, BufferPassGetsItsOwnTexture) {
  const ImageRgba8 image = Render(
      "buffer-texture",
      "void mainImage(out vec4 c, in vec2 p) { c = texelFetch(iChannel0, ivec2(p), 0); }\n",
      json::array({Input(0, "buffer", kBufferA, "nearest", "clamp")}),
      "void mainImage(out vec4 c, in vec2 p) {\n"
      "  c = vec4(iChannelResolution[1].x / 256.0, 0.0, texelFetch(iChannel1, ivec2(0), 0).b, "
      "1.0);\n}\n",
      json::array({Input(1, "texture", "/media/a/noise.png")}));
  ASSERT_EQ(image.pixels.size(), 8u * 8u * 4u);
  EXPECT_EQ(At(image, 3, 3, 0), 255);
  EXPECT_EQ(At(image, 3, 3, 2), 200);
}

// No key is down in a headless render: the keyboard texture is 256x3 of zeros.
TEST_F(PerPassChannels, KeyboardSamplesZero) {
  const ImageRgba8 image =
      Render("keyboard",
             "void mainImage(out vec4 c, in vec2 p) {\n"
             "  c = vec4(texture(iChannel0, p / iResolution.xy).rg,\n"
             "           iChannelResolution[0].y / 3.0 * iChannelResolution[0].x / 256.0, 1.0);\n"
             "}\n",
             json::array({Input(0, "keyboard", "/presets/tex00.jpg")}));
  ASSERT_EQ(image.pixels.size(), 8u * 8u * 4u);
  for (uint32_t y = 0; y < 8; ++y) {
    for (uint32_t x = 0; x < 8; ++x) {
      EXPECT_EQ(At(image, x, y, 0), 0) << x << "," << y;
      EXPECT_EQ(At(image, x, y, 1), 0) << x << "," << y;
      EXPECT_EQ(At(image, x, y, 2), 255) << x << "," << y;  // 256x3
    }
  }
}

// Buffer A has columns of 0 and 1; the Image pass reads it exactly on the edge
// between two texels: nearest gives one texel, linear their mean, and mipmap
// (level 3, one texel) the mean of the whole buffer, rebuilt after it was drawn.
TEST_F(PerPassChannels, BufferFilterFollowsTheSampler) {
  const std::string buffer =
      "void mainImage(out vec4 c, in vec2 p) { c = vec4(mod(floor(p.x), 2.0)); }\n";
  const std::string edge =
      "void mainImage(out vec4 c, in vec2 p) {\n"
      "  c = textureLod(iChannel0, vec2(floor(p.x) + 1.0, p.y) / iResolution.xy, 0.0);\n}\n";
  const ImageRgba8 nearest = Render(
      "nearest", edge, json::array({Input(0, "buffer", kBufferA, "nearest", "clamp")}), buffer);
  const ImageRgba8 linear = Render(
      "linear", edge, json::array({Input(0, "buffer", kBufferA, "linear", "clamp")}), buffer);
  const ImageRgba8 mipmap =
      Render("mipmap",
             "void mainImage(out vec4 c, in vec2 p) {\n"
             "  c = textureLod(iChannel0, p / iResolution.xy, 3.0);\n}\n",
             json::array({Input(0, "buffer", kBufferA, "mipmap", "clamp")}), buffer);
  ASSERT_EQ(nearest.pixels.size(), 8u * 8u * 4u);
  ASSERT_EQ(linear.pixels.size(), 8u * 8u * 4u);
  ASSERT_EQ(mipmap.pixels.size(), 8u * 8u * 4u);
  EXPECT_EQ(At(nearest, 2, 4, 0), 255);  // column 2 reads texel 3
  EXPECT_EQ(At(nearest, 3, 4, 0), 0);    // column 3 reads texel 4
  EXPECT_NEAR(At(linear, 2, 4, 0), 128, 1);
  EXPECT_NEAR(At(linear, 3, 4, 0), 128, 1);
  EXPECT_NEAR(At(mipmap, 5, 5, 0), 128, 1);
}

// Read beyond the right edge (u = 1.25): clamp gives the last texel, repeat the
// texel at u = 0.25.
TEST_F(PerPassChannels, BufferWrapFollowsTheSampler) {
  const std::string buffer = "void mainImage(out vec4 c, in vec2 p) { c = vec4(p.x / 8.0); }\n";
  const std::string outside =
      "void mainImage(out vec4 c, in vec2 p) {\n"
      "  c = texture(iChannel0, vec2(1.25, p.y / iResolution.y));\n}\n";
  const ImageRgba8 clamp = Render(
      "clamp", outside, json::array({Input(0, "buffer", kBufferA, "nearest", "clamp")}), buffer);
  const ImageRgba8 repeat = Render(
      "repeat", outside, json::array({Input(0, "buffer", kBufferA, "nearest", "repeat")}), buffer);
  ASSERT_EQ(clamp.pixels.size(), 8u * 8u * 4u);
  ASSERT_EQ(repeat.pixels.size(), 8u * 8u * 4u);
  EXPECT_EQ(At(clamp, 1, 1, 0), 239);  // texel 7: 7.5 / 8
  EXPECT_EQ(At(repeat, 1, 1, 0), 80);  // texel 2: 2.5 / 8
}

TEST(PerPassChannelsWire, ChannelsRoundTrip) {
  RenderRequest request;
  request.channels[1] = {PassChannelKind::kKeyboard, -1, ChannelFilter::kNearest,
                         ChannelWrap::kClamp, false};
  BufferPass pass;
  pass.channels[3] = {PassChannelKind::kBuffer, 2, ChannelFilter::kLinear, ChannelWrap::kRepeat,
                      true};
  request.buffer_passes.push_back(pass);
  const std::optional<RenderRequest> got = DecodeRequest(EncodeRequest(request));
  ASSERT_TRUE(got.has_value());
  EXPECT_EQ(got->channels[1].kind, PassChannelKind::kKeyboard);
  EXPECT_EQ(got->channels[1].filter, ChannelFilter::kNearest);
  EXPECT_EQ(got->channels[1].wrap, ChannelWrap::kClamp);
  EXPECT_FALSE(got->channels[1].vflip);
  EXPECT_EQ(got->channels[0].kind, PassChannelKind::kFromInputs);
  ASSERT_EQ(got->buffer_passes.size(), 1u);
  EXPECT_EQ(got->buffer_passes[0].channels[3].kind, PassChannelKind::kBuffer);
  EXPECT_EQ(got->buffer_passes[0].channels[3].buffer, 2);
  EXPECT_EQ(got->buffer_passes[0].channels[3].filter, ChannelFilter::kLinear);
  // A kind past the last one is refused, not misread.
  RenderRequest bad = request;
  bad.channels[1].kind = static_cast<PassChannelKind>(kLastPassChannelKind + 1);
  EXPECT_FALSE(DecodeRequest(EncodeRequest(bad)).has_value());
}

}  // namespace
}  // namespace shaderport::render
