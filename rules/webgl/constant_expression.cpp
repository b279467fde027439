#include "rules/webgl/constant_expression.h"

#include <optional>
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

const glsl::Declarator* InitializedDeclarator(const glsl::SyntaxTree& tree,
                                              const glsl::SemanticModel& model,
                                              const glsl::Expr& expr) {
  const uint32_t id = model.SymbolAt(expr.id);
  if (id == glsl::kNoSymbol) return nullptr;
  const glsl::Symbol& symbol = model.symbols[id];
  if (symbol.kind != glsl::SymbolKind::kVariable || symbol.declaration == glsl::kNoNode) {
    return nullptr;
  }
  const auto* declarator = tree.NodeAt(symbol.declaration).As<glsl::Declarator>();
  return declarator != nullptr && declarator->initializer != nullptr ? declarator : nullptr;
}

namespace {

constexpr int kMaxFoldDepth = 16;  // const variables defined by other const variables

class Folder {
 public:
  Folder(const glsl::SyntaxTree& tree, const glsl::SemanticModel& model)
      : tree_(tree), model_(model) {}

  std::optional<bool> Bool(const glsl::Expr* expr, int depth) const {
    expr = Unparenthesized(expr);
    if (expr == nullptr || depth > kMaxFoldDepth) return std::nullopt;
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

 private:
  static const glsl::Expr* Unparenthesized(const glsl::Expr* expr) {
    while (expr != nullptr && expr->kind == glsl::NodeKind::kParenExpr) {
      expr = static_cast<const glsl::ParenExpr*>(expr)->inner;
    }
    return expr;
  }

  const glsl::Declarator* ConstDeclarator(const glsl::Expr& expr) const {
    const uint32_t id = model_.SymbolAt(expr.id);
    if (id == glsl::kNoSymbol || !model_.symbols[id].is_const) return nullptr;
    return InitializedDeclarator(tree_, model_, expr);
  }

  // An int or float constant (ints up to 2^53 compare exactly as doubles).
  std::optional<double> Number(const glsl::Expr* expr, int depth) const {
    expr = Unparenthesized(expr);
    if (expr == nullptr || depth > kMaxFoldDepth) return std::nullopt;
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

  const glsl::SyntaxTree& tree_;
  const glsl::SemanticModel& model_;
};

}  // namespace

std::optional<bool> ConstantBool(const glsl::SyntaxTree& tree, const glsl::SemanticModel& model,
                                 const glsl::Expr& expr) {
  return Folder(tree, model).Bool(&expr, 0);
}

}  // namespace shaderport::rules::webgl
