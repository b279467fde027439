#include "render/request_wire.h"

#include <cstring>

#include "render/wire_codec.h"

namespace shaderport::render {
namespace {

using wire::Put;
using wire::PutString;
using wire::Reader;

// Bumped whenever the layout changes: both ends are the same binary, but a stale
// request must fail to decode rather than be misread.
constexpr uint32_t kMagic = 0x53505132;  // "SPQ2": per-pass channels
constexpr uint32_t kMaxBufferPasses = 64;

void PutInts(std::string& out, const std::array<int, 4>& values) {
  for (const int value : values) Put(out, static_cast<int32_t>(value));
}

void PutFloats(std::string& out, const std::array<float, 4>& values) {
  for (const float value : values) Put(out, value);
}

bool GetInts(Reader& in, std::array<int, 4>& values) {
  for (int& value : values) {
    int32_t v = 0;
    if (!in.Get(v)) return false;
    value = v;
  }
  return true;
}

bool GetFloats(Reader& in, std::array<float, 4>& values) {
  for (float& value : values) {
    if (!in.Get(value)) return false;
  }
  return true;
}

void PutChannel(std::string& out, const ChannelInput& channel) {
  Put(out, static_cast<uint8_t>(channel.kind));
  Put(out, static_cast<uint8_t>(channel.unbound));
  Put(out, channel.image.width);
  Put(out, channel.image.height);
  Put(out, static_cast<uint64_t>(channel.image.pixels.size()));
  out.append(reinterpret_cast<const char*>(channel.image.pixels.data()),
             channel.image.pixels.size());
}

bool GetChannel(Reader& in, ChannelInput& channel) {
  uint8_t kind = 0;
  uint64_t count = 0;
  if (!in.Get(kind) || kind > static_cast<uint8_t>(model::ChannelKind::k3D) ||
      !in.GetBool(channel.unbound) || !in.Get(channel.image.width) ||
      !in.Get(channel.image.height) || !in.Get(count) ||
      count != uint64_t{channel.image.width} * channel.image.height * 4 ||
      in.bytes.size() - in.at < count) {
    return false;
  }
  channel.kind = static_cast<model::ChannelKind>(kind);
  channel.image.pixels.assign(in.bytes.begin() + static_cast<std::ptrdiff_t>(in.at),
                              in.bytes.begin() + static_cast<std::ptrdiff_t>(in.at + count));
  in.at += count;
  return true;
}

void PutPassChannels(std::string& out, const PassChannels& channels) {
  for (const PassChannel& channel : channels) {
    Put(out, static_cast<uint8_t>(channel.kind));
    Put(out, static_cast<int32_t>(channel.buffer));
    Put(out, static_cast<uint8_t>(channel.filter));
    Put(out, static_cast<uint8_t>(channel.wrap));
    Put(out, static_cast<uint8_t>(channel.vflip));
  }
}

bool GetPassChannels(Reader& in, PassChannels& channels) {
  for (PassChannel& channel : channels) {
    uint8_t kind = 0;
    int32_t buffer = 0;
    uint8_t filter = 0;
    uint8_t wrap = 0;
    if (!in.Get(kind) || kind > kLastPassChannelKind || !in.Get(buffer) || buffer < -1 ||
        buffer > 3 || !in.Get(filter) || filter > static_cast<uint8_t>(ChannelFilter::kNearest) ||
        !in.Get(wrap) || wrap > static_cast<uint8_t>(ChannelWrap::kClamp) ||
        !in.GetBool(channel.vflip)) {
      return false;
    }
    channel.kind = static_cast<PassChannelKind>(kind);
    channel.buffer = buffer;
    channel.filter = static_cast<ChannelFilter>(filter);
    channel.wrap = static_cast<ChannelWrap>(wrap);
  }
  return true;
}

}  // namespace

std::string EncodeRequest(const RenderRequest& request) {
  std::string out;
  Put(out, kMagic);
  PutString(out, request.vertex_source);
  PutString(out, request.fragment_source);
  Put(out, static_cast<uint8_t>(request.fullscreen_vertex));
  Put(out, request.width);
  Put(out, request.height);
  Put(out, static_cast<int32_t>(request.frames));
  const ShaderToyInputs& inputs = request.inputs;
  Put(out, inputs.time);
  Put(out, static_cast<int32_t>(inputs.frame));
  Put(out, inputs.frame_rate);
  PutFloats(out, inputs.mouse);
  PutFloats(out, inputs.date);
  for (const ChannelInput& channel : inputs.channels) PutChannel(out, channel);
  Put(out, static_cast<uint32_t>(request.buffer_passes.size()));
  for (const BufferPass& pass : request.buffer_passes) {
    Put(out, static_cast<int32_t>(pass.buffer));
    PutString(out, pass.fragment_source);
    PutInts(out, pass.channel_buffers);
    PutPassChannels(out, pass.channels);
  }
  PutInts(out, request.channel_buffers);
  PutPassChannels(out, request.channels);
  PutString(out, request.probe_output);
  Put(out, static_cast<uint8_t>(request.probe_in_alpha));
  return out;
}

std::optional<RenderRequest> DecodeRequest(const std::string& bytes) {
  Reader in{bytes};
  RenderRequest request;
  uint32_t magic = 0;
  int32_t frames = 0;
  int32_t frame = 0;
  if (!in.Get(magic) || magic != kMagic || !in.GetString(request.vertex_source) ||
      !in.GetString(request.fragment_source) || !in.GetBool(request.fullscreen_vertex) ||
      !in.Get(request.width) || !in.Get(request.height) || !in.Get(frames) ||
      !in.Get(request.inputs.time) || !in.Get(frame) || !in.Get(request.inputs.frame_rate) ||
      !GetFloats(in, request.inputs.mouse) || !GetFloats(in, request.inputs.date)) {
    return std::nullopt;
  }
  request.frames = frames;
  request.inputs.frame = frame;
  for (ChannelInput& channel : request.inputs.channels) {
    if (!GetChannel(in, channel)) return std::nullopt;
  }
  uint32_t passes = 0;
  if (!in.Get(passes) || passes > kMaxBufferPasses) return std::nullopt;
  request.buffer_passes.resize(passes);
  for (BufferPass& pass : request.buffer_passes) {
    int32_t buffer = 0;
    if (!in.Get(buffer) || !in.GetString(pass.fragment_source) ||
        !GetInts(in, pass.channel_buffers) || !GetPassChannels(in, pass.channels)) {
      return std::nullopt;
    }
    pass.buffer = buffer;
  }
  if (!GetInts(in, request.channel_buffers) || !GetPassChannels(in, request.channels) ||
      !in.GetString(request.probe_output) || !in.GetBool(request.probe_in_alpha) ||
      in.at != bytes.size()) {
    return std::nullopt;
  }
  return request;
}

}  // namespace shaderport::render
