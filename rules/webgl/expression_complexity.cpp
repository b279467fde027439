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
#include <algorithm>
#include <optional>
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

// ANGLE builds its tree while parsing and folds as it goes (ParseContext.cpp):
//  - parentheses and expression statements make no node;
//  - the body of an `if`, `for`, `while` or `do` that is not a block is put in one
//    (EnsureBlock), a level of its own;
//  - `if` with a constant condition is replaced by the taken branch, as a block (the other
//    is dropped): `if (true) if (true) ... x = 1.0;` is one block however long;
//  - `c ? a : b` with a constant `c` is replaced by the operand it selects, but only when
//    that operand is a temporary like the `?:` itself (an operator's or call's result, or
//    a local variable), not a uniform, global, parameter or constant: the fold is kept
//    only when the qualifier does not change.
// Measured in Chromium 156: 126 nested unbraced `if (u > 0.5)`, `for` or `while` compile
// and 127 do not; 1,000 `if (true)` and 300 `true ? true ? ... a : b ...` compile.
class BrowserTree {
 public:
  explicit BrowserTree(const rule::RuleContext& context)
      : context_(context), rules_{context.Settings().source_version, nullptr} {}

  // Levels `node` adds under `parent` in the browser's tree; folded-away subtrees are
  // remembered and skipped (Dropped).
  uint32_t Levels(const glsl::Node& node, const glsl::Node* parent) {
    uint32_t own = 1;
    if (node.kind == glsl::NodeKind::kParenExpr ||
        node.kind == glsl::NodeKind::kExpressionStatement) {
      own = 0;
    } else if (const auto* branch = FoldedIf(node)) {
      own = 0;
      Drop(static_cast<const glsl::IfStatement&>(node), branch);
    } else if (node.kind == glsl::NodeKind::kConditionalExpr) {
      own = FoldConditional(static_cast<const glsl::ConditionalExpr&>(node)) ? 0 : 1;
    }
    return own + (IsUnbracedBody(node, parent) ? 1 : 0);
  }

  bool Dropped(const glsl::Node& node) const {
    return std::find(dropped_.begin(), dropped_.end(), &node) != dropped_.end();
  }

  bool Constant(const glsl::Expr& expr) const {
    return webgl::IsConstantExpression(context_.Model(), expr, rules_);
  }

 private:
  // The `if` itself when its condition is constant (it becomes the taken branch), or
  // nullptr.
  const glsl::Node* FoldedIf(const glsl::Node& node) const {
    if (node.kind != glsl::NodeKind::kIfStatement) return nullptr;
    const auto& statement = static_cast<const glsl::IfStatement&>(node);
    if (statement.condition == nullptr || !Constant(*statement.condition)) return nullptr;
    return &node;
  }

  // Drops what the fold removes: the condition, and the branch not taken when the
  // condition's value is known here (otherwise both are walked: the deeper one bounds
  // the depth).
  void Drop(const glsl::IfStatement& statement, const glsl::Node* /*folded*/) {
    dropped_.push_back(statement.condition);
    const std::optional<bool> value =
        webgl::ConstantBool(context_.Tree(), context_.Model(), *statement.condition);
    if (!value) return;
    const glsl::Node* untaken = *value ? statement.else_branch : statement.then_branch;
    if (untaken != nullptr) dropped_.push_back(untaken);
  }

  bool FoldConditional(const glsl::ConditionalExpr& conditional) {
    if (conditional.condition == nullptr || conditional.if_true == nullptr ||
        conditional.if_false == nullptr || !Constant(*conditional.condition)) {
      return false;
    }
    // ANGLE keeps the fold only when the selected operand is a temporary; when the
    // condition's value is not known here, only when both are.
    const std::optional<bool> value =
        webgl::ConstantBool(context_.Tree(), context_.Model(), *conditional.condition);
    const glsl::Expr* if_true = webgl::Unparenthesized(conditional.if_true);
    const glsl::Expr* if_false = webgl::Unparenthesized(conditional.if_false);
    const bool folds = value ? IsTemporary(*value ? *if_true : *if_false)
                             : IsTemporary(*if_true) && IsTemporary(*if_false);
    if (!folds) return false;
    dropped_.push_back(conditional.condition);
    if (value) dropped_.push_back(*value ? conditional.if_false : conditional.if_true);
    return true;
  }

  bool IsTemporary(const glsl::Expr& expr) const {
    if (expr.kind == glsl::NodeKind::kIdentifierExpr) {
      const glsl::Symbol* symbol = webgl::SymbolOf(context_, expr);
      return symbol != nullptr && symbol->kind == glsl::SymbolKind::kVariable &&
             !symbol->is_const && symbol->scope != 0 && symbol->declaration != glsl::kNoNode &&
             context_.Tree().NodeAt(symbol->declaration).kind == glsl::NodeKind::kDeclarator;
    }
    return !Constant(expr);
  }

  // A statement that is the body of a loop or a branch of an `if` and that the browser
  // puts in a block of its own: neither a block nor an `if` folded into one.
  bool IsUnbracedBody(const glsl::Node& node, const glsl::Node* parent) const {
    if (parent == nullptr || node.kind == glsl::NodeKind::kCompoundStatement ||
        FoldedIf(node) != nullptr) {
      return false;
    }
    switch (parent->kind) {
      case glsl::NodeKind::kIfStatement: {
        const auto& statement = static_cast<const glsl::IfStatement&>(*parent);
        return &node == statement.then_branch || &node == statement.else_branch;
      }
      case glsl::NodeKind::kForStatement:
        return &node == static_cast<const glsl::ForStatement&>(*parent).body;
      case glsl::NodeKind::kWhileStatement:
        return &node == static_cast<const glsl::WhileStatement&>(*parent).body;
      case glsl::NodeKind::kDoWhileStatement:
        return &node == static_cast<const glsl::DoWhileStatement&>(*parent).body;
      default:
        return false;
    }
  }

  const rule::RuleContext& context_;
  webgl::ConstantRules rules_;
  std::vector<const glsl::Node*> dropped_;  // few: one or two per folded node
};

// The depth of the browser's tree (BrowserTree); a constant expression is one leaf. Run
// only where our own tree is too deep, since it asks whether expressions are constant.
// Returns the statement too deep, or nullptr.
const glsl::Node* TooDeepInBrowser(const rule::RuleContext& context) {
  BrowserTree browser(context);
  std::vector<uint32_t> levels;         // the browser's depth of the node at each of our depths
  std::vector<const glsl::Node*> path;  // our node at each depth
  const glsl::Node* statement = nullptr;
  const glsl::Node* found = nullptr;
  glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, uint32_t depth) {
    if (found != nullptr) return false;
    levels.resize(depth + 1);
    path.resize(depth + 1);
    path[depth] = &node;
    if (browser.Dropped(node)) return false;
    if (!node.IsExpr()) statement = &node;
    const glsl::Node* parent = depth == 0 ? nullptr : path[depth - 1];
    levels[depth] = (depth == 0 ? 0 : levels[depth - 1]) + browser.Levels(node, parent);
    if (levels[depth] > kMaxDepth + 1) {
      found = statement != nullptr ? statement : &node;
      return false;
    }
    const auto* expr = node.IsExpr() ? static_cast<const glsl::Expr*>(&node) : nullptr;
    const bool leaf = expr != nullptr && node.kind != glsl::NodeKind::kParenExpr &&
                      node.kind != glsl::NodeKind::kLiteralExpr &&
                      node.kind != glsl::NodeKind::kIdentifierExpr && browser.Constant(*expr);
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
    // The browser's tree has at most twice our levels (an unbraced body adds a block
    // under each `if` or loop), so shallower trees need no second look.
    const glsl::SyntaxTree& tree = context.Tree();
    if (tree.Root() != nullptr && !tree.Preorder().empty()) {
      // Every node up to the first too deep one is visited: a plain loop over the index
      // (the root's entry is the first, at depth 0).
      const std::span<const glsl::PreorderEntry> order = tree.Preorder();
      for (const glsl::PreorderEntry& entry : order) {
        if (entry.depth <= kMaxDepth / 2) continue;
        // Our tree is deep here; the browser's may be deeper (blocks around unbraced
        // bodies) or shallower (parentheses, folding).
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
