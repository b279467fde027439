#include "glsl/syntax/visit.h"

#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

namespace shaderport::glsl {

// Flattened: the per-child callbacks of ForEachChild were out-of-line calls, and this
// runs over every node of every tree. The parser places each node once, so the work
// stack and the open entries fit in arrays of the node count, written by index; a
// shared node (never made by the parser) would overflow them, and falls back to
// vectors that grow.
[[gnu::flatten]] void SyntaxTree::IndexPreorder() {
  preorder_.clear();
  preorder_kinds_.clear();
  preorder_index_.assign(nodes_.size(), kNotInPreorder);
  if (root_ == nullptr) return;
  const size_t capacity = nodes_.size() + 1;  // + 1: a root made outside the tree
  preorder_.resize(capacity);
  preorder_kinds_.resize(capacity);
  const auto stack = std::make_unique_for_overwrite<PreorderItem[]>(capacity);
  // Indices of the entries whose subtree is still open, deepest last: an entry's subtree
  // ends where the next node no deeper than it is placed.
  const auto open = std::make_unique_for_overwrite<uint32_t[]>(capacity);
  size_t stack_size = 0;
  size_t open_size = 0;
  uint32_t count = 0;
  bool overflow = false;
  stack[stack_size++] = {root_, 0};
  while (stack_size != 0) {
    const PreorderItem item = stack[--stack_size];
    if (count == capacity) {
      overflow = true;
      break;
    }
    const uint32_t index = count++;
    while (open_size != 0 && preorder_[open[open_size - 1]].depth >= item.depth) {
      preorder_[open[--open_size]].end = index;
    }
    preorder_index_[item.node->id] = index;
    preorder_[index] = {item.node, item.depth, 0};
    preorder_kinds_[index] = item.node->kind;
    open[open_size++] = index;
    const size_t first = stack_size;
    ForEachChild(*item.node, [&](const Node& child) {
      if (stack_size == capacity) {
        overflow = true;
        return;
      }
      stack[stack_size++] = {&child, item.depth + 1};
    });
    if (overflow) break;
    std::reverse(stack.get() + first, stack.get() + stack_size);
  }
  if (overflow) return IndexSharedPreorder();
  for (size_t i = 0; i < open_size; ++i) preorder_[open[i]].end = count;
  preorder_.resize(count);
  preorder_kinds_.resize(count);
}

void SyntaxTree::IndexSharedPreorder() {
  preorder_.clear();
  preorder_kinds_.clear();
  preorder_index_.assign(nodes_.size(), kNotInPreorder);
  std::vector<PreorderItem> stack{{root_, 0}};
  std::vector<uint32_t> open;
  while (!stack.empty()) {
    const PreorderItem item = stack.back();
    stack.pop_back();
    const auto index = static_cast<uint32_t>(preorder_.size());
    while (!open.empty() && preorder_[open.back()].depth >= item.depth) {
      preorder_[open.back()].end = index;
      open.pop_back();
    }
    preorder_index_[item.node->id] = index;
    preorder_.push_back({item.node, item.depth, 0});
    preorder_kinds_.push_back(item.node->kind);
    open.push_back(index);
    const size_t first = stack.size();
    ForEachChild(*item.node, [&](const Node& child) { stack.push_back({&child, item.depth + 1}); });
    std::reverse(stack.begin() + static_cast<std::ptrdiff_t>(first), stack.end());
  }
  const auto size = static_cast<uint32_t>(preorder_.size());
  for (const uint32_t index : open) preorder_[index].end = size;
}

void VisitPostorder(const Node& start, const std::function<void(const Node& node)>& fn) {
  // Each entry holds a node and its children, gathered on first visit.
  struct Frame {
    const Node* node;
    std::vector<const Node*> children;
    size_t next = 0;
  };
  std::vector<Frame> stack;
  auto push = [&](const Node* node) {
    Frame frame{node, {}, 0};
    ForEachChild(*node, [&](const Node& child) { frame.children.push_back(&child); });
    stack.push_back(std::move(frame));
  };
  push(&start);
  while (!stack.empty()) {
    Frame& top = stack.back();
    if (top.next < top.children.size()) {
      push(top.children[top.next++]);
      continue;
    }
    const Node* done = top.node;
    stack.pop_back();
    fn(*done);
  }
}

void VisitPostorder(const SyntaxTree& tree, const std::function<void(const Node& node)>& fn) {
  if (tree.Root() != nullptr) VisitPostorder(*tree.Root(), fn);
}

}  // namespace shaderport::glsl
