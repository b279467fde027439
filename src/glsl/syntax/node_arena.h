// The bump allocator that holds a SyntaxTree's nodes (not public API).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace shaderport::glsl {

// Hands out memory from blocks that double in size and are freed together. The fast
// path is inline: every node of every tree is placed here, and the out-of-line virtual
// call of std::pmr::monotonic_buffer_resource was a twentieth of the parse.
class NodeArena {
 public:
  NodeArena() = default;
  NodeArena(const NodeArena&) = delete;
  NodeArena& operator=(const NodeArena&) = delete;

  void* Allocate(size_t size, size_t alignment) {
    const uintptr_t at = (next_ + alignment - 1) & ~(uintptr_t{alignment} - 1);
    if (at + size > end_) return AllocateInNewBlock(size, alignment);
    next_ = at + size;
    return reinterpret_cast<void*>(at);
  }

 private:
  // A small shader's nodes fit in the first block.
  static constexpr size_t kFirstBlockBytes = size_t{16} << 10;
  void* AllocateInNewBlock(size_t size, size_t alignment);

  std::vector<std::unique_ptr<std::byte[]>> blocks_;
  uintptr_t next_ = 0;  // the free part of the newest block
  uintptr_t end_ = 0;
  size_t next_block_bytes_ = kFirstBlockBytes;
};

}  // namespace shaderport::glsl
