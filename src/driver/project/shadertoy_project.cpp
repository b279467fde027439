#include "driver/project/shadertoy_project.h"

#include <algorithm>

namespace shaderport::driver::project {

const ChannelBinding* ProjectPass::Input(int channel) const {
  for (const ChannelBinding& input : inputs)
    if (input.channel == channel) return &input;
  return nullptr;
}

const ProjectPass* ShaderToyProject::Find(model::PassKind kind) const {
  for (const ProjectPass& pass : passes)
    if (pass.kind == kind) return &pass;
  return nullptr;
}

std::vector<const ProjectPass*> ShaderToyProject::BuffersInOrder() const {
  std::vector<const ProjectPass*> buffers;
  for (const ProjectPass& pass : passes)
    if (pass.kind == model::PassKind::kBuffer && pass.output_buffer >= 0) buffers.push_back(&pass);
  std::stable_sort(buffers.begin(), buffers.end(), [](const ProjectPass* a, const ProjectPass* b) {
    return a->output_buffer < b->output_buffer;
  });
  return buffers;
}

std::optional<int> BufferIndexFromName(std::string_view tab_name) {
  if (tab_name.size() != 8 || !tab_name.starts_with("Buffer ")) return std::nullopt;
  const char letter = tab_name[7];
  if (letter < 'A' || letter > 'D') return std::nullopt;
  return letter - 'A';
}

std::optional<int> BufferIndexFromSource(std::string_view src) {
  const size_t at = src.find("buffer0");
  if (at == std::string_view::npos || at + 7 >= src.size()) return std::nullopt;
  const char digit = src[at + 7];
  if (digit < '0' || digit > '3') return std::nullopt;
  return digit - '0';
}

std::string BufferTabName(int index) {
  return std::string("Buffer ") + static_cast<char>('A' + index);
}

std::string TabName(model::PassKind kind, int buffer) {
  switch (kind) {
    case model::PassKind::kImage:
      return "Image";
    case model::PassKind::kBuffer:
      return BufferTabName(buffer >= 0 && buffer < 4 ? buffer : 0);
    case model::PassKind::kCommon:
      return "Common";
    case model::PassKind::kCube:
      return "Cube A";
    case model::PassKind::kSound:
      return "Sound";
  }
  return "Image";
}

std::string FolderFileName(const ProjectPass& pass) {
  switch (pass.kind) {
    case model::PassKind::kCommon:
      return "common.glsl";
    case model::PassKind::kCube:
      return "cube-a.glsl";
    case model::PassKind::kSound:
      return "sound.glsl";
    case model::PassKind::kImage:
      return "image.glsl";
    case model::PassKind::kBuffer:
      return std::string("buffer-") + static_cast<char>('a' + std::max(pass.output_buffer, 0)) +
             ".glsl";
  }
  return "image.glsl";
}

}  // namespace shaderport::driver::project
