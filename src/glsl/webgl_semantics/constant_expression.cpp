// Which expressions a browser's compiler folds to constants before the driver sees
// them (ANGLE folds literals, const variables, operators, constructors and
// built-in calls on constants), and where a call sits.
#include <functional>

#include "glsl/syntax/visit.h"
#include "glsl/webgl_semantics/semantics_context.h"

namespace shaderport::glsl {
namespace {

constexpr int kMaxConstantDepth = 64;

// Built-ins whose value depends on more than their arguments.
bool FoldableBuiltin(std::string_view name) {
  return !name.starts_with("texture") && !name.starts_with("dFd") && name != "fwidth";
}

}  // namespace

bool IsConstantTree(const Expr* expr, const SemanticModel& model,
                    const std::function<bool(const Expr& identifier, int depth)>& identifier,
                    int depth, const std::function<bool(const CallExpr& call)>& builtin) {
  if (expr == nullptr || depth > kMaxConstantDepth) return false;
  auto constant = [&](const Expr* operand) {
    return IsConstantTree(operand, model, identifier, depth + 1, builtin);
  };
  switch (expr->kind) {
    case NodeKind::kLiteralExpr:
      return true;
    case NodeKind::kIdentifierExpr:
      return identifier(*expr, depth + 1);
    case NodeKind::kParenExpr:
      return constant(expr->As<ParenExpr>()->inner);
    case NodeKind::kUnaryExpr: {
      const auto* unary = expr->As<UnaryExpr>();
      return unary->op != UnaryOp::kPreIncrement && unary->op != UnaryOp::kPreDecrement &&
             unary->op != UnaryOp::kPostIncrement && unary->op != UnaryOp::kPostDecrement &&
             constant(unary->operand);
    }
    case NodeKind::kBinaryExpr: {
      const auto* binary = expr->As<BinaryExpr>();
      return binary->op != BinaryOp::kComma && constant(binary->lhs) && constant(binary->rhs);
    }
    case NodeKind::kConditionalExpr: {
      const auto* conditional = expr->As<ConditionalExpr>();
      return constant(conditional->condition) && constant(conditional->if_true) &&
             constant(conditional->if_false);
    }
    case NodeKind::kMemberExpr:
      return constant(expr->As<MemberExpr>()->object);
    case NodeKind::kIndexExpr: {
      const auto* index = expr->As<IndexExpr>();
      return constant(index->base) && constant(index->index);
    }
    case NodeKind::kCallExpr: {
      const auto* call = expr->As<CallExpr>();
      const bool folded_builtin = call->call_kind == CallKind::kFunction &&
                                  model.builtin_calls.contains(call->id) &&
                                  (builtin ? builtin(*call) : FoldableBuiltin(call->callee.text));
      if ((call->call_kind != CallKind::kConstructor && !folded_builtin) ||
          call->arguments.empty()) {
        return false;
      }
      for (const Expr* argument : call->arguments) {
        if (!constant(argument)) return false;
      }
      return true;
    }
    default:
      return false;
  }
}

bool IsConstantExpression(const Expr* expr, const SemanticModel& model) {
  return IsConstantTree(expr, model, [&](const Expr& identifier, int) {
    const uint32_t symbol = model.SymbolAt(identifier.id);
    return symbol != kNoSymbol && model.symbols[symbol].is_const;
  });
}

bool InsideFunctionBody(const SemanticsContext& c, const Node& node) {
  for (const Node* at = c.Parent(node); at != nullptr; at = c.Parent(*at)) {
    if (at->kind == NodeKind::kCompoundStatement && c.Parent(*at) != nullptr &&
        c.Parent(*at)->kind == NodeKind::kFunctionDeclaration) {
      return true;
    }
  }
  return false;
}

}  // namespace shaderport::glsl
