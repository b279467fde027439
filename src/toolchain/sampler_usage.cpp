#include "toolchain/sampler_usage.h"

#include <cstdint>
#include <unordered_map>

namespace shaderport::toolchain {
namespace {

// SPIR-V opcodes and image-operand bits used here (SPIR-V spec §3.14, §3.32).
enum Op : uint32_t {
  kOpName = 5,
  kOpVariable = 59,
  kOpLoad = 61,
  kOpCopyObject = 83,
  kOpSampledImage = 86,
  kOpImageSampleImplicitLod = 87,
  kOpImageSampleExplicitLod = 88,
  kOpImageSampleDrefImplicitLod = 89,
  kOpImageSampleDrefExplicitLod = 90,
  kOpImageSampleProjImplicitLod = 91,
  kOpImageSampleProjExplicitLod = 92,
  kOpImageSampleProjDrefImplicitLod = 93,
  kOpImageSampleProjDrefExplicitLod = 94,
  kOpImageFetch = 95,
  kOpImageGather = 96,
  kOpImageDrefGather = 97,
  kOpImage = 100,
  kOpImageQuerySizeLod = 103,
  kOpImageQuerySize = 104,
  kOpImageQueryLod = 105,
  kOpImageQueryLevels = 106,
};
constexpr uint32_t kGradBit = 0x4;
constexpr uint32_t kOffsetBits = 0x8 | 0x10;  // ConstOffset | Offset

std::string DecodeString(const uint32_t* words, size_t count) {
  std::string text;
  for (size_t i = 0; i < count; ++i) {
    for (int b = 0; b < 4; ++b) {
      const char c = static_cast<char>((words[i] >> (8 * b)) & 0xff);
      if (c == '\0') return text;
      text += c;
    }
  }
  return text;
}

// GLSL name of an image instruction; `operands` is its image-operands mask (0 if none).
std::string FunctionName(uint32_t opcode, uint32_t operands) {
  const bool grad = (operands & kGradBit) != 0;
  const std::string offset = (operands & kOffsetBits) != 0 ? "Offset" : "";
  switch (opcode) {
    case kOpImageSampleImplicitLod:
    case kOpImageSampleDrefImplicitLod:
      return "texture" + offset;
    case kOpImageSampleExplicitLod:
    case kOpImageSampleDrefExplicitLod:
      return (grad ? "textureGrad" : "textureLod") + offset;
    case kOpImageSampleProjImplicitLod:
    case kOpImageSampleProjDrefImplicitLod:
      return "textureProj" + offset;
    case kOpImageSampleProjExplicitLod:
    case kOpImageSampleProjDrefExplicitLod:
      return (grad ? "textureProjGrad" : "textureProjLod") + offset;
    case kOpImageFetch:
      return "texelFetch" + offset;
    case kOpImageGather:
    case kOpImageDrefGather:
      return "textureGather" + offset;
    case kOpImageQuerySizeLod:
    case kOpImageQuerySize:
      return "textureSize";
    case kOpImageQueryLod:
      return "textureQueryLod";
    case kOpImageQueryLevels:
      return "textureQueryLevels";
    default:
      return "";
  }
}

// Word index of the image-operands mask, or 0 for instructions that have none.
size_t OperandsIndex(uint32_t opcode) {
  switch (opcode) {
    case kOpImageSampleImplicitLod:
    case kOpImageSampleExplicitLod:
    case kOpImageSampleProjImplicitLod:
    case kOpImageSampleProjExplicitLod:
    case kOpImageFetch:
      return 5;
    case kOpImageSampleDrefImplicitLod:
    case kOpImageSampleDrefExplicitLod:
    case kOpImageSampleProjDrefImplicitLod:
    case kOpImageSampleProjDrefExplicitLod:
    case kOpImageGather:
    case kOpImageDrefGather:
      return 6;
    default:
      return 0;
  }
}

}  // namespace

std::map<std::string, std::set<std::string>> SamplerOperations(const SpirvWords& words) {
  std::map<std::string, std::set<std::string>> result;
  std::unordered_map<uint32_t, std::string> names;
  std::unordered_map<uint32_t, uint32_t> origin;  // value id -> global variable id
  std::unordered_map<uint32_t, bool> is_variable;
  auto trace = [&](uint32_t id) -> uint32_t {
    if (is_variable.count(id)) return id;
    const auto it = origin.find(id);
    return it == origin.end() ? 0 : it->second;
  };
  constexpr size_t kHeaderWords = 5;
  for (size_t at = kHeaderWords; at < words.size();) {
    const uint32_t count = words[at] >> 16;
    const uint32_t opcode = words[at] & 0xffff;
    if (count == 0 || at + count > words.size()) break;  // malformed: stop, never overrun
    const uint32_t* w = &words[at];
    if (opcode == kOpName && count >= 3) {
      names[w[1]] = DecodeString(w + 2, count - 2);
    } else if (opcode == kOpVariable && count >= 4) {
      is_variable[w[2]] = true;
    } else if ((opcode == kOpLoad || opcode == kOpCopyObject || opcode == kOpSampledImage ||
                opcode == kOpImage) &&
               count >= 4) {
      if (const uint32_t source = trace(w[3]); source != 0) origin[w[2]] = source;
    } else if (const std::string function = FunctionName(opcode, 0);
               !function.empty() && count >= 4) {
      const size_t index = OperandsIndex(opcode);
      const uint32_t operands = index != 0 && index < count ? w[index] : 0;
      if (const uint32_t source = trace(w[3]); source != 0 && names.count(source)) {
        result[names[source]].insert(FunctionName(opcode, operands));
      }
    }
    at += count;
  }
  return result;
}

}  // namespace shaderport::toolchain
