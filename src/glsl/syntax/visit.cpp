#include "glsl/syntax/visit.h"

#include <utility>
#include <vector>

namespace shaderport::glsl {

void SyntaxTree::IndexPreorder() {
  preorder_.clear();
  preorder_index_.assign(nodes_.size(), kNotInPreorder);
  if (root_ == nullptr) return;
  preorder_.reserve(nodes_.size());
  // An entry with node == nullptr closes the subtree of preorder_[value]: it pops
  // after all of that node's descendants were appended.
  struct Item {
    const Node* node;
    uint32_t value;  // the depth to open a node, the preorder index to close one
  };
  std::vector<Item> stack{{root_, 0}};
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    const auto index = static_cast<uint32_t>(preorder_.size());
    if (item.node == nullptr) {
      preorder_[item.value].end = index;
      continue;
    }
    preorder_index_[item.node->id] = index;
    preorder_.push_back({item.node, item.value, 0});
    stack.push_back({nullptr, index});
    const size_t first = stack.size();
    ForEachChild(*item.node, [&](const Node& child) { stack.push_back({&child, item.value + 1}); });
    std::reverse(stack.begin() + static_cast<std::ptrdiff_t>(first), stack.end());
  }
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
