// Which expressions a browser's compiler folds to constants before the driver sees
// them (ANGLE folds literals, const variables, operators, constructors and
// built-in calls on constants), and where a call sits.
#include "glsl/syntax/visit.h"
#include "glsl/webgl_semantics/semantics_context.h"

namespace shaderport::glsl {
namespace {

constexpr int kMaxConstantDepth = 64;

// Built-ins whose value depends on more than their arguments.
bool FoldableBuiltin(std::string_view name) {
  return !name.starts_with("texture") && !name.starts_with("dFd") && name != "fwidth";
}

bool IsConstant(const Expr* expr, const SemanticModel& model, int depth) {
  if (expr == nullptr || depth > kMaxConstantDepth) return false;
  switch (expr->kind) {
    case NodeKind::kLiteralExpr:
      return true;
    case NodeKind::kIdentifierExpr: {
      const uint32_t symbol = model.SymbolAt(expr->id);
      return symbol != kNoSymbol && model.symbols[symbol].is_const;
    }
    case NodeKind::kParenExpr:
      return IsConstant(expr->As<ParenExpr>()->inner, model, depth + 1);
    case NodeKind::kUnaryExpr: {
      const auto* unary = expr->As<UnaryExpr>();
      return unary->op != UnaryOp::kPreIncrement && unary->op != UnaryOp::kPreDecrement &&
             unary->op != UnaryOp::kPostIncrement && unary->op != UnaryOp::kPostDecrement &&
             IsConstant(unary->operand, model, depth + 1);
    }
    case NodeKind::kBinaryExpr: {
      const auto* binary = expr->As<BinaryExpr>();
      return binary->op != BinaryOp::kComma && IsConstant(binary->lhs, model, depth + 1) &&
             IsConstant(binary->rhs, model, depth + 1);
    }
    case NodeKind::kConditionalExpr: {
      const auto* conditional = expr->As<ConditionalExpr>();
      return IsConstant(conditional->condition, model, depth + 1) &&
             IsConstant(conditional->if_true, model, depth + 1) &&
             IsConstant(conditional->if_false, model, depth + 1);
    }
    case NodeKind::kMemberExpr: {
      const auto* member = expr->As<MemberExpr>();
      return IsConstant(member->object, model, depth + 1);
    }
    case NodeKind::kCallExpr: {
      const auto* call = expr->As<CallExpr>();
      const bool builtin = call->call_kind == CallKind::kFunction &&
                           model.builtin_calls.contains(call->id) &&
                           FoldableBuiltin(call->callee.text);
      if (call->call_kind != CallKind::kConstructor && !builtin) return false;
      if (call->arguments.empty()) return false;
      for (const Expr* argument : call->arguments) {
        if (!IsConstant(argument, model, depth + 1)) return false;
      }
      return true;
    }
    default:
      return false;
  }
}

}  // namespace

bool IsConstantExpression(const Expr* expr, const SemanticModel& model) {
  return IsConstant(expr, model, 0);
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
