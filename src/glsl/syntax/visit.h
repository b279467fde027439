// Generic traversal of a SyntaxTree: children of a node in source order and a
// preorder walk that never recurses (left-associative chains such as `a+b+c+...`
// can make the tree deeper than the parser's recursion limit).
//
// The walks are templates so the callback is called directly, not through
// std::function: every WebGL rule walks every node of the tree. Walks given the
// tree use its preorder index (SyntaxTree::Preorder), a loop over an array built
// once per tree; walks given only a node fall back to an explicit stack.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "glsl/syntax/ast.h"
#include "glsl/syntax/children.h"

namespace shaderport::glsl {
namespace visit_detail {

// `fn(node, depth)` over the subtree at `order[begin]`, depths relative to it.
template <class Fn>
void WalkIndexed(std::span<const PreorderEntry> order, uint32_t begin, Fn& fn) {
  const uint32_t end = order[begin].end;
  const uint32_t base = order[begin].depth;
  for (uint32_t i = begin; i < end;) {
    const PreorderEntry& entry = order[i];
    i = fn(*entry.node, entry.depth - base) ? i + 1 : entry.end;
  }
}

template <class Fn>
void WalkWithStack(const Node& start, Fn& fn) {
  std::vector<std::pair<const Node*, uint32_t>> stack{{&start, 0}};
  while (!stack.empty()) {
    // Not a structured binding: clang 14 cannot capture one in the lambda below.
    const Node* node = stack.back().first;
    const uint32_t depth = stack.back().second;
    stack.pop_back();
    if (!fn(*node, depth)) continue;
    // Pushed in source order, then reversed so that the first child pops first.
    const size_t first = stack.size();
    ForEachChild(*node, [&](const Node& child) { stack.emplace_back(&child, depth + 1); });
    std::reverse(stack.begin() + static_cast<std::ptrdiff_t>(first), stack.end());
  }
}

}  // namespace visit_detail

/// Walks the tree in preorder from the root. `fn(node, depth)` returns false to
/// skip the node's children. The root has depth 0.
template <class Fn>
void VisitPreorder(const SyntaxTree& tree, Fn&& fn) {
  if (tree.Root() == nullptr) return;
  if (!tree.Preorder().empty()) return visit_detail::WalkIndexed(tree.Preorder(), 0, fn);
  visit_detail::WalkWithStack(*tree.Root(), fn);
}

/// Same, from `start`, a node of `tree` (depth 0 at `start`).
template <class Fn>
void VisitPreorder(const SyntaxTree& tree, const Node& start, Fn&& fn) {
  const uint32_t at = tree.PreorderIndexOf(start.id);
  if (at != SyntaxTree::kNotInPreorder && tree.Preorder()[at].node == &start) {
    return visit_detail::WalkIndexed(tree.Preorder(), at, fn);
  }
  visit_detail::WalkWithStack(start, fn);
}

/// Same, from any node, without the tree's index (an explicit stack).
template <class Fn>
void VisitPreorder(const Node& start, Fn&& fn) {
  visit_detail::WalkWithStack(start, fn);
}

/// Calls `fn` on every node after all its children (children in source order):
/// the order to compute bottom-up facts such as expression types without recursion.
void VisitPostorder(const SyntaxTree& tree, const std::function<void(const Node& node)>& fn);
void VisitPostorder(const Node& start, const std::function<void(const Node& node)>& fn);

}  // namespace shaderport::glsl
