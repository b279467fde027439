// The request a parent sends its render worker survives the trip field by field,
// and a truncated or altered message is refused rather than half-read.
#include "render/request_wire.h"

#include <gtest/gtest.h>

namespace shaderport::render {
namespace {

RenderRequest EveryFieldSet() {
  RenderRequest request;
  request.vertex_source = "#version 300 es\nvoid main() {}\n";
  request.fragment_source = std::string("frag\0with nul", 13);
  request.fullscreen_vertex = true;
  request.width = 33;
  request.height = 17;
  request.frames = 3;
  request.inputs.time = 2.5f;
  request.inputs.frame = 9;
  request.inputs.frame_rate = 30.0f;
  request.inputs.mouse = {1, 2, 3, 4};
  request.inputs.date = {2024, 5, 6, 7};
  request.inputs.channels[1].kind = model::ChannelKind::kCube;
  request.inputs.channels[2].unbound = true;
  request.inputs.channels[3].image = {2, 1, {1, 2, 3, 4, 5, 6, 7, 8}};
  request.buffer_passes.push_back({2, "buffer text", {0, -1, 2, 3}});
  request.buffer_passes.push_back({0, "", {-1, -1, -1, 1}});
  request.channel_buffers = {3, -1, 0, 1};
  request.probe_output = "shaderport_probe";
  request.probe_in_alpha = true;
  return request;
}

TEST(RequestWire, EveryFieldRoundTrips) {
  const RenderRequest sent = EveryFieldSet();
  const std::optional<RenderRequest> got = DecodeRequest(EncodeRequest(sent));
  ASSERT_TRUE(got.has_value());
  EXPECT_EQ(got->vertex_source, sent.vertex_source);
  EXPECT_EQ(got->fragment_source, sent.fragment_source);
  EXPECT_EQ(got->fullscreen_vertex, sent.fullscreen_vertex);
  EXPECT_EQ(got->width, sent.width);
  EXPECT_EQ(got->height, sent.height);
  EXPECT_EQ(got->frames, sent.frames);
  EXPECT_EQ(got->inputs.time, sent.inputs.time);
  EXPECT_EQ(got->inputs.frame, sent.inputs.frame);
  EXPECT_EQ(got->inputs.frame_rate, sent.inputs.frame_rate);
  EXPECT_EQ(got->inputs.mouse, sent.inputs.mouse);
  EXPECT_EQ(got->inputs.date, sent.inputs.date);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(got->inputs.channels[i].kind, sent.inputs.channels[i].kind) << i;
    EXPECT_EQ(got->inputs.channels[i].unbound, sent.inputs.channels[i].unbound) << i;
    EXPECT_EQ(got->inputs.channels[i].image.width, sent.inputs.channels[i].image.width) << i;
    EXPECT_EQ(got->inputs.channels[i].image.height, sent.inputs.channels[i].image.height) << i;
    EXPECT_EQ(got->inputs.channels[i].image.pixels, sent.inputs.channels[i].image.pixels) << i;
  }
  ASSERT_EQ(got->buffer_passes.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(got->buffer_passes[i].buffer, sent.buffer_passes[i].buffer);
    EXPECT_EQ(got->buffer_passes[i].fragment_source, sent.buffer_passes[i].fragment_source);
    EXPECT_EQ(got->buffer_passes[i].channel_buffers, sent.buffer_passes[i].channel_buffers);
  }
  EXPECT_EQ(got->channel_buffers, sent.channel_buffers);
  EXPECT_EQ(got->probe_output, sent.probe_output);
  EXPECT_EQ(got->probe_in_alpha, sent.probe_in_alpha);
}

TEST(RequestWire, TruncatedOrExtendedMessagesAreRefused) {
  const std::string bytes = EncodeRequest(EveryFieldSet());
  for (size_t size = 0; size < bytes.size(); ++size) {
    EXPECT_FALSE(DecodeRequest(bytes.substr(0, size)).has_value()) << size;
  }
  EXPECT_FALSE(DecodeRequest(bytes + "x").has_value());
  std::string wrong_magic = bytes;
  wrong_magic[0] ^= 1;
  EXPECT_FALSE(DecodeRequest(wrong_magic).has_value());
}

TEST(RequestWire, ImageSizeMustMatchItsPixels) {
  RenderRequest request;
  request.inputs.channels[0].image = {4, 4, {1, 2, 3, 4}};  // 16 pixels claimed, 1 sent
  EXPECT_FALSE(DecodeRequest(EncodeRequest(request)).has_value());
}

}  // namespace
}  // namespace shaderport::render
