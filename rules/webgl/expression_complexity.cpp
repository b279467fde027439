// webgl/expression-complexity: code nested deeper than browsers compile. Chromium
// compiles WebGL shaders with ANGLE's expression complexity limit: a syntax tree
// deeper than 256 levels (for example a chain of 1,000 `+`) is rejected with
// "Expression too complex". glslang has no such limit.
//
//   gl_FragColor = u + u + u + ... + u;   // 1,000 operators: error
#include <string>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/expression-complexity";
// ANGLE's MaxExpressionComplexity as Chromium sets it for WebGL.
constexpr uint32_t kMaxDepth = 256;

// Out of line, so that the walk's callback stays small enough to be inlined (it runs for
// every node of every tree; the report for at most one).
[[gnu::noinline]] void ReportTooDeep(rule::RuleContext& context, const SourceRange& range) {
  webgl::ReportError(context, kId, range,
                     "expression too complex: its syntax tree is more than " +
                         std::to_string(kMaxDepth) +
                         " levels deep, and browsers reject such shaders; split it into "
                         "several statements");
}

class ExpressionComplexityRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "Code nested deeper than browsers compile (256 levels)",
                                     "gl_FragColor = u + u + u + /* ... 1,000 times */ u;", "",
                                     rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    // Our tree has about as many levels as the browser's (a function, its body,
    // a statement, then the expression).
    const glsl::Node* statement = nullptr;
    const glsl::SyntaxTree& tree = context.Tree();
    if (tree.Root() != nullptr && !tree.Preorder().empty()) {
      // Every node up to the first too deep one is visited: a plain loop over the index
      // (the root's entry is the first, at depth 0).
      // The kind table says which nodes are statements without reading the nodes.
      const std::span<const glsl::PreorderEntry> order = tree.Preorder();
      const std::span<const glsl::NodeKind> kinds = tree.PreorderKinds();
      size_t statement_at = order.size();
      for (size_t i = 0; i < order.size(); ++i) {
        if (kinds[i] < glsl::NodeKind::kIdentifierExpr) statement_at = i;
        if (order[i].depth <= kMaxDepth) continue;
        ReportTooDeep(context, statement_at != order.size() ? order[statement_at].node->range
                                                            : order[i].node->range);
        return;
      }
      return;
    }
    bool reported = false;
    glsl::VisitPreorder(tree, [&](const glsl::Node& node, uint32_t depth) {
      if (reported) return false;
      if (!node.IsExpr()) statement = &node;
      if (depth <= kMaxDepth) return true;
      ReportTooDeep(context, statement != nullptr ? statement->range : node.range);
      reported = true;
      return false;
    });
  }
};

}  // namespace

const rule::Rule& WebglExpressionComplexityRule() {
  static const ExpressionComplexityRule rule;
  return rule;
}

}  // namespace shaderport::rules
