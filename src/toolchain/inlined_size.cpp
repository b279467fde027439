#include "toolchain/inlined_size.h"

#include <glslang/SPIRV/spirv.hpp>
#include <limits>
#include <unordered_map>
#include <vector>

namespace shaderport::toolchain {
namespace {

constexpr size_t kHeaderWords = 5;  // magic, version, generator, bound, schema

struct Function {
  uint64_t own = 0;               // instructions, calls included
  std::vector<uint32_t> callees;  // one per call
};

uint64_t SaturatingAdd(uint64_t a, uint64_t b) {
  return a > std::numeric_limits<uint64_t>::max() - b ? std::numeric_limits<uint64_t>::max()
                                                      : a + b;
}

}  // namespace

uint64_t InlinedInstructionCount(const SpirvWords& words) {
  std::unordered_map<uint32_t, Function> functions;
  uint32_t entry = 0;
  Function* current = nullptr;
  for (size_t i = kHeaderWords; i < words.size();) {
    const uint32_t opcode = words[i] & 0xffffu;
    const uint32_t count = words[i] >> 16;
    if (count == 0 || i + count > words.size()) break;  // malformed: stop counting
    if (opcode == spv::OpEntryPoint && count > 2 && entry == 0) entry = words[i + 2];
    if (opcode == spv::OpFunction && count > 2) current = &functions[words[i + 2]];
    if (current != nullptr) {
      ++current->own;
      if (opcode == spv::OpFunctionCall && count > 3) current->callees.push_back(words[i + 3]);
    }
    if (opcode == spv::OpFunctionEnd) current = nullptr;
    i += count;
  }
  if (!functions.contains(entry)) return 0;

  // Post-order over the call graph with an explicit stack (GLSL has no recursion; a
  // cycle in a malformed module counts its back edge as nothing).
  std::unordered_map<uint32_t, uint64_t> inlined;
  std::unordered_map<uint32_t, bool> open;
  std::vector<std::pair<uint32_t, size_t>> stack{{entry, 0}};
  open[entry] = true;
  while (!stack.empty()) {
    auto& [id, next] = stack.back();
    const Function& function = functions.at(id);
    if (next < function.callees.size()) {
      const uint32_t callee = function.callees[next++];
      if (!inlined.contains(callee) && !open[callee] && functions.contains(callee)) {
        open[callee] = true;
        stack.emplace_back(callee, 0);
      }
      continue;
    }
    uint64_t total = function.own;
    for (const uint32_t callee : function.callees) {
      const auto found = inlined.find(callee);
      if (found != inlined.end()) total = SaturatingAdd(total, found->second);
    }
    inlined[id] = total;
    open[id] = false;
    stack.pop_back();
  }
  return inlined[entry];
}

}  // namespace shaderport::toolchain
