#include "glsl/syntax/visit.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace shaderport::glsl {

void SyntaxTree::IndexPreorder() {
  preorder_.clear();
  preorder_index_.assign(nodes_.size(), kNotInPreorder);
  if (root_ == nullptr) return;
  preorder_.reserve(nodes_.size());
  struct Item {
    const Node* node;
    uint32_t depth;
  };
  std::vector<Item> stack{{root_, 0}};  // nodes still to index, the next one last
  // Indices of the entries whose subtree is still open, deepest last: an entry's subtree
  // ends where the next node no deeper than it is placed.
  std::vector<uint32_t> open;
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    const auto index = static_cast<uint32_t>(preorder_.size());
    while (!open.empty() && preorder_[open.back()].depth >= item.depth) {
      preorder_[open.back()].end = index;
      open.pop_back();
    }
    preorder_index_[item.node->id] = index;
    preorder_.push_back({item.node, item.depth, 0});
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
