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
#include <initializer_list>
#include <span>
#include <type_traits>
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

/// A set of node kinds, for the walks that look at a few kinds only.
class NodeKinds {
 public:
  constexpr NodeKinds(std::initializer_list<NodeKind> kinds) {
    for (NodeKind kind : kinds) bits_ |= uint64_t{1} << static_cast<unsigned>(kind);
  }
  constexpr bool Has(NodeKind kind) const {
    return ((bits_ >> static_cast<unsigned>(kind)) & 1u) != 0;
  }

 private:
  static_assert(static_cast<unsigned>(NodeKind::kErrorExpr) < 64);
  uint64_t bits_ = 0;
};

namespace visit_detail {

// fn(node) for a node of a wanted kind; true to go on into its subtree. An `fn` that
// returns nothing always goes on.
template <class Fn>
bool CallOnMatch(Fn& fn, const Node& node) {
  if constexpr (std::is_same_v<std::invoke_result_t<Fn&, const Node&>, bool>) {
    return fn(node);
  } else {
    fn(node);
    return true;
  }
}

}  // namespace visit_detail

/// Calls `fn(node)` on every node of one of `kinds` in the subtree of `start` (a node
/// of `tree`, itself included), in preorder; an `fn` that returns false skips the
/// node's subtree. With the tree's index this scans its kind table and reads no
/// other node: most rules look at a few kinds, and reading every node of a large
/// tree for each of them misses the cache node after node.
template <class Fn>
void ForEachNodeOf(const SyntaxTree& tree, const Node& start, NodeKinds kinds, Fn&& fn) {
  const uint32_t at = tree.PreorderIndexOf(start.id);
  if (at == SyntaxTree::kNotInPreorder || tree.Preorder()[at].node != &start) {
    auto filtered = [&](const Node& node, uint32_t) {
      return !kinds.Has(node.kind) || visit_detail::CallOnMatch(fn, node);
    };
    visit_detail::WalkWithStack(start, filtered);
    return;
  }
  const std::span<const PreorderEntry> order = tree.Preorder();
  const std::span<const NodeKind> kind_of = tree.PreorderKinds();
  for (uint32_t i = at, end = order[at].end; i < end;) {
    if (!kinds.Has(kind_of[i])) {
      ++i;
    } else {
      i = visit_detail::CallOnMatch(fn, *order[i].node) ? i + 1 : order[i].end;
    }
  }
}

/// Same over the whole tree.
template <class Fn>
void ForEachNodeOf(const SyntaxTree& tree, NodeKinds kinds, Fn&& fn) {
  if (tree.Root() != nullptr) ForEachNodeOf(tree, *tree.Root(), kinds, fn);
}

/// Calls `fn` on every node after all its children (children in source order):
/// the order to compute bottom-up facts such as expression types without recursion.
void VisitPostorder(const SyntaxTree& tree, const std::function<void(const Node& node)>& fn);
void VisitPostorder(const Node& start, const std::function<void(const Node& node)>& fn);

}  // namespace shaderport::glsl
