// ForEachNodeOf: the walk over a few node kinds that reads only those nodes.
#include <gtest/gtest.h>

#include <vector>

#include "syntax/parse_helpers.h"

namespace shaderport::glsl {
namespace {

using testing::ParseText;

constexpr const char* kShader =
    "struct S { float a; };\n"
    "float f(float x) { float y = x * 2.0; return y + f(y); }\n"
    "void main() { S s = S(1.0); float z = f(s.a) + f(2.0); }\n";

// The nodes of `kinds` in the order a full preorder walk meets them.
std::vector<const Node*> ByFullWalk(const SyntaxTree& tree, const Node& start, NodeKinds kinds) {
  std::vector<const Node*> found;
  VisitPreorder(tree, start, [&](const Node& node, uint32_t) {
    if (kinds.Has(node.kind)) found.push_back(&node);
    return true;
  });
  return found;
}

TEST(KindWalkTest, FindsTheNodesOfTheKindsInPreorder) {
  const auto parsed = ParseText(kShader);
  const SyntaxTree& tree = parsed->result.tree;
  ASSERT_EQ(tree.PreorderKinds().size(), tree.Preorder().size());
  const NodeKinds kinds = {NodeKind::kCallExpr, NodeKind::kDeclarator};
  std::vector<const Node*> found;
  ForEachNodeOf(tree, kinds, [&](const Node& node) { found.push_back(&node); });
  EXPECT_EQ(found, ByFullWalk(tree, *tree.Root(), kinds));
  EXPECT_EQ(found.size(), 8u);  // y, f(y), s, S(1.0), z, f(s.a), f(2.0), and the field a
}

TEST(KindWalkTest, StaysInsideTheSubtreeItIsGiven) {
  const auto parsed = ParseText(kShader);
  const SyntaxTree& tree = parsed->result.tree;
  const auto* function = parsed->Root().declarations[1]->As<FunctionDeclaration>();
  ASSERT_NE(function, nullptr);
  std::vector<const Node*> calls;
  ForEachNodeOf(tree, *function->body, {NodeKind::kCallExpr},
                [&](const Node& node) { calls.push_back(&node); });
  ASSERT_EQ(calls.size(), 1u);  // f(y), not the calls in main
  EXPECT_EQ(calls, ByFullWalk(tree, *function->body, {NodeKind::kCallExpr}));
}

TEST(KindWalkTest, FalseSkipsTheSubtreeOfAMatch) {
  // Every call, but not the calls nested inside another one's arguments.
  const auto nested = ParseText("void main() { float a = max(min(1.0, 2.0), 3.0); }\n");
  int outer = 0;
  ForEachNodeOf(nested->result.tree, {NodeKind::kCallExpr}, [&](const Node&) {
    ++outer;
    return false;
  });
  EXPECT_EQ(outer, 1);
  int all = 0;
  ForEachNodeOf(nested->result.tree, {NodeKind::kCallExpr}, [&](const Node&) {
    ++all;
    return true;
  });
  EXPECT_EQ(all, 2);
}

TEST(KindWalkTest, ANodeOutsideTheIndexIsWalkedWithoutIt) {
  const auto parsed = ParseText(kShader);
  const auto other = ParseText("float g() { return sin(1.0) + cos(2.0); }\n");
  // A node of another tree has no entry in this tree's index: the walk still finds
  // its calls, through the explicit stack.
  int calls = 0;
  ForEachNodeOf(parsed->result.tree, other->Root(), {NodeKind::kCallExpr},
                [&](const Node&) { ++calls; });
  EXPECT_EQ(calls, 2);
}

}  // namespace
}  // namespace shaderport::glsl
