#include "glsl/syntax/node_arena.h"

#include <algorithm>

namespace shaderport::glsl {

void* NodeArena::AllocateInNewBlock(size_t size, size_t alignment) {
  // new[] aligns to __STDCPP_DEFAULT_NEW_ALIGNMENT__; the slack covers any larger need.
  const size_t bytes = std::max(next_block_bytes_, size + alignment);
  next_block_bytes_ = bytes * 2;
  blocks_.push_back(std::make_unique_for_overwrite<std::byte[]>(bytes));
  next_ = reinterpret_cast<uintptr_t>(blocks_.back().get());
  end_ = next_ + bytes;
  const uintptr_t at = (next_ + alignment - 1) & ~(uintptr_t{alignment} - 1);
  next_ = at + size;
  return reinterpret_cast<void*>(at);
}

}  // namespace shaderport::glsl
