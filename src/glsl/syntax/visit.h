// Generic traversal of a SyntaxTree: children of a node in source order and a
// preorder walk that uses an explicit stack (left-associative chains such as
// `a+b+c+...` can make the tree deeper than the parser's recursion limit).
#pragma once

#include <functional>

#include "glsl/syntax/ast.h"

namespace shaderport::glsl {

/// Calls `fn` on each direct child of `node` in source order (null slots skipped).
void ForEachChild(const Node& node, const std::function<void(const Node&)>& fn);

/// Walks the tree in preorder from the root. `fn(node, depth)` returns false to
/// skip the node's children. The root has depth 0.
void VisitPreorder(const SyntaxTree& tree,
                   const std::function<bool(const Node& node, uint32_t depth)>& fn);

/// Same, from any node.
void VisitPreorder(const Node& start,
                   const std::function<bool(const Node& node, uint32_t depth)>& fn);

/// Calls `fn` on every node after all its children (children in source order):
/// the order to compute bottom-up facts such as expression types without recursion.
void VisitPostorder(const SyntaxTree& tree, const std::function<void(const Node& node)>& fn);
void VisitPostorder(const Node& start, const std::function<void(const Node& node)>& fn);

}  // namespace shaderport::glsl
