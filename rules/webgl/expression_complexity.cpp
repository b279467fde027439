// webgl/expression-complexity: code nested deeper than browsers compile. Chromium
// compiles WebGL shaders with ANGLE's expression complexity limit: a syntax tree
// deeper than 256 levels (for example a chain of 1,000 `+`) is rejected with
// "Expression too complex". glslang has no such limit. ANGLE's tree has no nodes for
// parentheses, and it folds constant expressions into one node while parsing, so
// `((((y))))` and `1.0 + 1.0 + ... + 1.0` add no depth there (measured in Chromium 156:
// `y + y + ...` compiles with 252 operands, not with 253; 3,000 nested parentheses and
// 5,000 constant terms compile).
//
//   gl_FragColor = u + u + u + ... + u;   // 1,000 operators: error
#include <string>
#include <vector>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/constant_expression.h"
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

// The depth of the browser's tree: parentheses take no level, and a constant
// expression is one leaf. Run only where our own tree is too deep, since it asks
// whether expressions are constant. Returns the statement too deep, or nullptr.
const glsl::Node* TooDeepInBrowser(const rule::RuleContext& context) {
  const webgl::ConstantRules rules{context.Settings().source_version, nullptr};
  std::vector<uint32_t> levels;  // the browser's depth of the node at each of our depths
  const glsl::Node* statement = nullptr;
  const glsl::Node* found = nullptr;
  glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, uint32_t depth) {
    if (found != nullptr) return false;
    if (!node.IsExpr()) statement = &node;
    levels.resize(depth + 1);
    const uint32_t parent = depth == 0 ? 0 : levels[depth - 1];
    levels[depth] = parent + (node.kind == glsl::NodeKind::kParenExpr ? 0 : 1);
    if (levels[depth] > kMaxDepth + 1) {
      found = statement != nullptr ? statement : &node;
      return false;
    }
    const auto* expr = node.IsExpr() ? static_cast<const glsl::Expr*>(&node) : nullptr;
    const bool leaf = expr != nullptr && node.kind != glsl::NodeKind::kParenExpr &&
                      node.kind != glsl::NodeKind::kLiteralExpr &&
                      node.kind != glsl::NodeKind::kIdentifierExpr &&
                      webgl::IsConstantExpression(context.Model(), *expr, rules);
    return !leaf;
  });
  return found;
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
    // a statement, then the expression), and never fewer.
    const glsl::SyntaxTree& tree = context.Tree();
    if (tree.Root() != nullptr && !tree.Preorder().empty()) {
      // Every node up to the first too deep one is visited: a plain loop over the index
      // (the root's entry is the first, at depth 0).
      const std::span<const glsl::PreorderEntry> order = tree.Preorder();
      for (size_t i = 0; i < order.size(); ++i) {
        if (order[i].depth <= kMaxDepth) continue;
        // Our tree is too deep here; the browser's may not be (parentheses, folding).
        if (const glsl::Node* statement = TooDeepInBrowser(context)) {
          ReportTooDeep(context, statement->range);
        }
        return;
      }
      return;
    }
    if (tree.Root() == nullptr) return;
    if (const glsl::Node* too_deep = TooDeepInBrowser(context)) {
      ReportTooDeep(context, too_deep->range);
    }
  }
};

}  // namespace

const rule::Rule& WebglExpressionComplexityRule() {
  static const ExpressionComplexityRule rule;
  return rule;
}

}  // namespace shaderport::rules
