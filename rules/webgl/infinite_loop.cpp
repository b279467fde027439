// webgl/infinite-loop: a loop browsers reject as infinite. ANGLE, compiling for WebGL,
// rejects a `for` or `while` loop (not `do ... while`) whose condition is missing,
// constant and true, or a variable initialised to true that nothing else reads or
// writes, when no `break` of its own and no `return` leaves it ("Infinite loop detected
// in the shader", Chromium 156; ANGLE's PruneInfiniteLoops). `discard` does not count as
// a way out, and the loop is rejected even in a function nothing calls. glslang accepts
// such loops; portability/infinite-loop is the broader lint for loops that never end.
//
//   for (;;) { if (u > 0.5) discard; }   // error: no break or return
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/infinite-loop";
constexpr int kMaxDepth = 16;  // const variables defined by other const variables

// A `break` of this loop (not of a nested loop or switch), or a `return` anywhere in it.
bool HasWayOut(const glsl::Node& body) {
  bool way_out = false;
  glsl::VisitPreorder(body, [&](const glsl::Node& node, int /*depth*/) {
    if (way_out) return false;
    way_out = node.kind == glsl::NodeKind::kReturnStatement;
    return !way_out;
  });
  if (way_out) return true;
  glsl::VisitPreorder(body, [&](const glsl::Node& node, int /*depth*/) {
    if (way_out) return false;
    if (node.kind == glsl::NodeKind::kForStatement ||
        node.kind == glsl::NodeKind::kWhileStatement ||
        node.kind == glsl::NodeKind::kDoWhileStatement ||
        node.kind == glsl::NodeKind::kSwitchStatement) {
      return false;
    }
    way_out = node.kind == glsl::NodeKind::kBreakStatement;
    return !way_out;
  });
  return way_out;
}

class ConditionValues {
 public:
  explicit ConditionValues(const rule::RuleContext& context) : context_(context) {}

  // The value of a constant condition ANGLE folds: literals, `!`, `&&`, `||`, integer
  // and float comparisons and const variables of them; nullopt for anything else.
  std::optional<bool> Bool(const glsl::Expr* expr, int depth = 0) const {
    expr = webgl::Unparenthesized(expr);
    if (expr == nullptr || depth > kMaxDepth) return std::nullopt;
    if (const auto* literal = expr->As<glsl::LiteralExpr>()) {
      if (literal->literal_kind != glsl::LiteralKind::kBool) return std::nullopt;
      return literal->bool_value;
    }
    if (const auto* unary = expr->As<glsl::UnaryExpr>()) {
      if (unary->op != glsl::UnaryOp::kNot) return std::nullopt;
      const std::optional<bool> operand = Bool(unary->operand, depth + 1);
      return operand ? std::optional<bool>(!*operand) : std::nullopt;
    }
    if (const auto* binary = expr->As<glsl::BinaryExpr>()) return Binary(*binary, depth);
    if (expr->kind == glsl::NodeKind::kIdentifierExpr) {
      const glsl::Declarator* declarator = ConstDeclarator(*expr);
      return declarator != nullptr ? Bool(declarator->initializer, depth + 1) : std::nullopt;
    }
    return std::nullopt;
  }

  // The declarator of the variable `expr` names, when it is a variable (not a
  // parameter) with an initializer; nullptr otherwise.
  const glsl::Declarator* Declaration(const glsl::Expr& expr) const {
    const glsl::Symbol* symbol = webgl::SymbolOf(context_, expr);
    if (symbol == nullptr || symbol->kind != glsl::SymbolKind::kVariable ||
        symbol->declaration == glsl::kNoNode) {
      return nullptr;
    }
    const auto* declarator = context_.Tree().NodeAt(symbol->declaration).As<glsl::Declarator>();
    return declarator != nullptr && declarator->initializer != nullptr ? declarator : nullptr;
  }

 private:
  const glsl::Declarator* ConstDeclarator(const glsl::Expr& expr) const {
    const glsl::Symbol* symbol = webgl::SymbolOf(context_, expr);
    return symbol != nullptr && symbol->is_const ? Declaration(expr) : nullptr;
  }

  // An int or float constant (ints up to 2^53 compare exactly as doubles).
  std::optional<double> Number(const glsl::Expr* expr, int depth) const {
    expr = webgl::Unparenthesized(expr);
    if (expr == nullptr || depth > kMaxDepth) return std::nullopt;
    if (const auto* literal = expr->As<glsl::LiteralExpr>()) {
      if (literal->literal_kind == glsl::LiteralKind::kInt) {
        return static_cast<double>(literal->int_value);
      }
      if (literal->literal_kind == glsl::LiteralKind::kFloat) return literal->float_value;
      return std::nullopt;
    }
    if (expr->kind == glsl::NodeKind::kIdentifierExpr) {
      const glsl::Declarator* declarator = ConstDeclarator(*expr);
      return declarator != nullptr ? Number(declarator->initializer, depth + 1) : std::nullopt;
    }
    return std::nullopt;
  }

  std::optional<bool> Binary(const glsl::BinaryExpr& binary, int depth) const {
    using Op = glsl::BinaryOp;
    if (binary.op == Op::kLogicalAnd || binary.op == Op::kLogicalOr) {
      const std::optional<bool> lhs = Bool(binary.lhs, depth + 1);
      const std::optional<bool> rhs = Bool(binary.rhs, depth + 1);
      if (!lhs || !rhs) return std::nullopt;
      return binary.op == Op::kLogicalAnd ? (*lhs && *rhs) : (*lhs || *rhs);
    }
    const std::optional<double> lhs = Number(binary.lhs, depth + 1);
    const std::optional<double> rhs = Number(binary.rhs, depth + 1);
    if (!lhs || !rhs) return std::nullopt;
    switch (binary.op) {
      case Op::kLess:
        return *lhs < *rhs;
      case Op::kGreater:
        return *lhs > *rhs;
      case Op::kLessEqual:
        return *lhs <= *rhs;
      case Op::kGreaterEqual:
        return *lhs >= *rhs;
      case Op::kEqual:
        return *lhs == *rhs;
      case Op::kNotEqual:
        return *lhs != *rhs;
      default:
        return std::nullopt;
    }
  }

  const rule::RuleContext& context_;
};

class InfiniteLoopRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "A loop browsers reject as infinite",
                                     "for (;;) { if (u > 0.5) discard; }", "",
                                     rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const ConditionValues values(context);
    struct Loop {
      const glsl::Node* node;
      const glsl::Node* condition;
      const glsl::Node* body;
    };
    std::vector<Loop> loops;
    std::vector<const glsl::Node*> bare_conditions;  // identifiers that are a whole condition
    glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, uint32_t /*depth*/) {
      if (const auto* for_loop = node.As<glsl::ForStatement>()) {
        loops.push_back({&node, for_loop->condition, for_loop->body});
      } else if (const auto* while_loop = node.As<glsl::WhileStatement>()) {
        loops.push_back({&node, while_loop->condition, while_loop->body});
      } else {
        return true;
      }
      const glsl::Node* condition = loops.back().condition;
      if (condition != nullptr && condition->IsExpr()) {
        const glsl::Expr* bare = webgl::Unparenthesized(static_cast<const glsl::Expr*>(condition));
        if (bare != nullptr && bare->kind == glsl::NodeKind::kIdentifierExpr) {
          bare_conditions.push_back(bare);
        }
      }
      return true;
    });
    for (const Loop& loop : loops) {
      if (loop.body == nullptr || !AlwaysTrue(context, values, loop.condition, bare_conditions) ||
          HasWayOut(*loop.body)) {
        continue;
      }
      webgl::ReportError(context, kId, loop.node->range,
                         "browsers reject this loop as infinite ('Infinite loop detected in the "
                         "shader'): its condition never changes and no 'break' or 'return' "
                         "leaves it ('discard' does not count)");
    }
  }

 private:
  static bool AlwaysTrue(const rule::RuleContext& context, const ConditionValues& values,
                         const glsl::Node* condition,
                         const std::vector<const glsl::Node*>& bare_conditions) {
    if (condition == nullptr || condition->kind == glsl::NodeKind::kEmptyStatement) return true;
    if (!condition->IsExpr()) return false;
    const auto* expr = static_cast<const glsl::Expr*>(condition);
    if (values.Bool(expr) == true) return true;
    // A variable initialised to true that nothing reads or writes but loop conditions.
    const glsl::Expr* bare = webgl::Unparenthesized(expr);
    if (bare == nullptr || bare->kind != glsl::NodeKind::kIdentifierExpr) return false;
    const glsl::Declarator* declarator = values.Declaration(*bare);
    if (declarator == nullptr || values.Bool(declarator->initializer) != true) return false;
    const uint32_t symbol = context.Model().SymbolAt(bare->id);
    bool other_use = false;
    glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, uint32_t /*depth*/) {
      if (other_use) return false;
      if (node.kind == glsl::NodeKind::kIdentifierExpr &&
          context.Model().SymbolAt(node.id) == symbol &&
          std::find(bare_conditions.begin(), bare_conditions.end(), &node) ==
              bare_conditions.end()) {
        other_use = true;
      }
      return !other_use;
    });
    return !other_use;
  }
};

}  // namespace

const rule::Rule& WebglInfiniteLoopRule() {
  static const InfiniteLoopRule rule;
  return rule;
}

}  // namespace shaderport::rules
