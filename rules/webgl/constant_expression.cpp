#include "rules/webgl/constant_expression.h"

#include <string_view>
#include <vector>

namespace shaderport::rules::webgl {
namespace {

// Built-ins whose value depends on more than their arguments.
bool NeverConstant(std::string_view name) {
  return name.starts_with("texture") || name.starts_with("shadow") || name == "dFdx" ||
         name == "dFdy" || name == "fwidth" || name.starts_with("textureSize");
}

}  // namespace

bool IsConstantExpression(const glsl::SemanticModel& model, const glsl::Expr& expr,
                          const ConstantRules& rules) {
  std::vector<const glsl::Expr*> pending = {&expr};
  while (!pending.empty()) {
    const glsl::Expr* node = pending.back();
    pending.pop_back();
    if (node == nullptr) return false;
    switch (node->kind) {
      case glsl::NodeKind::kLiteralExpr:
        break;
      case glsl::NodeKind::kIdentifierExpr: {
        const uint32_t symbol = model.SymbolAt(node->id);
        if (symbol == glsl::kNoSymbol) return false;
        if (rules.loop_indices != nullptr && rules.loop_indices->contains(symbol)) break;
        const glsl::Symbol& variable = model.symbols[symbol];
        const bool is_variable = variable.kind == glsl::SymbolKind::kVariable ||
                                 variable.kind == glsl::SymbolKind::kBuiltinVariable;
        if (!is_variable || !variable.is_const) return false;
        break;
      }
      case glsl::NodeKind::kParenExpr:
        pending.push_back(static_cast<const glsl::ParenExpr*>(node)->inner);
        break;
      case glsl::NodeKind::kUnaryExpr: {
        const auto* unary = static_cast<const glsl::UnaryExpr*>(node);
        if (unary->op >= glsl::UnaryOp::kPreIncrement) return false;
        pending.push_back(unary->operand);
        break;
      }
      case glsl::NodeKind::kBinaryExpr: {
        const auto* binary = static_cast<const glsl::BinaryExpr*>(node);
        // GLSL ES 3.00 section 4.3.3 leaves the sequence operator out of constant
        // expressions, and browsers follow it there; GLSL ES 1.00 code keeps it.
        if (binary->op == glsl::BinaryOp::kComma && rules.version >= 300) return false;
        pending.push_back(binary->lhs);
        pending.push_back(binary->rhs);
        break;
      }
      case glsl::NodeKind::kConditionalExpr: {
        const auto* conditional = static_cast<const glsl::ConditionalExpr*>(node);
        pending.push_back(conditional->condition);
        pending.push_back(conditional->if_true);
        pending.push_back(conditional->if_false);
        break;
      }
      case glsl::NodeKind::kCallExpr: {
        const auto* call = static_cast<const glsl::CallExpr*>(node);
        if (call->call_kind == glsl::CallKind::kMethod) break;  // `a.length()`
        if (call->call_kind == glsl::CallKind::kFunction) {
          if (!model.builtin_calls.contains(call->id)) return false;  // user functions
          if (NeverConstant(call->callee.text)) return false;
        }
        for (const glsl::Expr* argument : call->arguments) pending.push_back(argument);
        break;
      }
      case glsl::NodeKind::kMemberExpr:
        pending.push_back(static_cast<const glsl::MemberExpr*>(node)->object);
        break;
      case glsl::NodeKind::kIndexExpr: {
        const auto* index = static_cast<const glsl::IndexExpr*>(node);
        pending.push_back(index->base);
        pending.push_back(index->index);
        break;
      }
      default:
        return false;
    }
  }
  return true;
}

}  // namespace shaderport::rules::webgl
