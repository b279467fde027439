#include "rules/typing/global_initializer_check.h"

#include <unordered_set>

#include "glsl/syntax/visit.h"
#include "rules/typing/typing_support.h"

namespace shaderport::rules::typing {
namespace {

bool IsNonConstantBuiltin(std::string_view name) {
  return name.starts_with("texture") || name.starts_with("shadow") || name == "dFdx" ||
         name == "dFdy" || name == "fwidth";
}

const glsl::Symbol* SymbolOf(const rule::RuleContext& context, const glsl::Node& node) {
  const glsl::SemanticModel& model = context.Model();
  const uint32_t symbol = model.SymbolAt(node.id);
  return symbol < model.symbols.size() ? &model.symbols[symbol] : nullptr;
}

}  // namespace

Constness ClassifyInitializer(const rule::RuleContext& context, const glsl::Expr& e) {
  Constness result = Constness::kConstant;
  const glsl::SemanticModel& model = context.Model();
  glsl::VisitPreorder(context.Tree(), e, [&](const glsl::Node& node, uint32_t) {
    if (result == Constness::kUnknown) return false;
    switch (node.kind) {
      case glsl::NodeKind::kErrorExpr:
        result = Constness::kUnknown;
        return false;
      case glsl::NodeKind::kAssignmentExpr:
        result = Constness::kNotConstant;
        break;
      case glsl::NodeKind::kUnaryExpr: {
        const auto op = node.As<glsl::UnaryExpr>()->op;
        if (op != glsl::UnaryOp::kPlus && op != glsl::UnaryOp::kMinus &&
            op != glsl::UnaryOp::kNot && op != glsl::UnaryOp::kBitNot) {
          result = Constness::kNotConstant;
        }
        break;
      }
      case glsl::NodeKind::kIdentifierExpr: {
        const glsl::Symbol* symbol = SymbolOf(context, node);
        if (symbol == nullptr) {
          result = Constness::kUnknown;
          return false;
        }
        if (!symbol->is_const) result = Constness::kNotConstant;
        break;
      }
      case glsl::NodeKind::kCallExpr: {
        const auto* call = node.As<glsl::CallExpr>();
        if (call->call_kind != glsl::CallKind::kFunction) break;
        if (model.builtin_calls.contains(call->id)) {
          if (IsNonConstantBuiltin(call->callee.text)) result = Constness::kNotConstant;
          break;
        }
        const glsl::Symbol* symbol = SymbolOf(context, node);
        if (symbol == nullptr) {
          result = Constness::kUnknown;
          return false;
        }
        if (symbol->kind != glsl::SymbolKind::kStruct) result = Constness::kNotConstant;
        break;
      }
      default:
        break;
    }
    return true;
  });
  return result;
}

std::string WhyNotMovable(const rule::RuleContext& context, const glsl::Expr& e) {
  std::string why;
  const glsl::SemanticModel& model = context.Model();
  glsl::VisitPreorder(context.Tree(), e, [&](const glsl::Node& node, uint32_t) {
    if (!why.empty()) return false;
    if (node.kind == glsl::NodeKind::kIdentifierExpr) {
      const glsl::Symbol* symbol = SymbolOf(context, node);
      if (symbol == nullptr || symbol->scope != 0) {
        why = "it reads '" + node.As<glsl::IdentifierExpr>()->name + "', which is not a global";
      }
    } else if (const auto* call = node.As<glsl::CallExpr>();
               call != nullptr && call->call_kind == glsl::CallKind::kFunction &&
               !model.builtin_calls.contains(call->id)) {
      const glsl::Symbol* symbol = SymbolOf(context, node);
      if (symbol == nullptr || symbol->kind != glsl::SymbolKind::kStruct) {
        why = "it calls the function '" + call->callee.text + "'";
      }
    }
    return why.empty();
  });
  return why;
}

bool HasTypingFindings(const rule::RuleContext& context, const glsl::Expr& e) {
  std::unordered_set<uint32_t> sites;
  for (const IntForFloatSite& site : IntForFloatSites(context)) sites.insert(site.expr->id);
  for (const glsl::TypeMismatch& m : context.Model().mismatches) sites.insert(m.node);
  const glsl::SemanticModel& model = context.Model();
  bool found = false;
  glsl::VisitPreorder(context.Tree(), e, [&](const glsl::Node& node, uint32_t) {
    if (sites.contains(node.id)) found = true;
    if (const auto* b = node.As<glsl::BinaryExpr>();
        b != nullptr && b->op == glsl::BinaryOp::kMod) {
      if (model.TypeOf(b->lhs->id).base == glsl::BaseType::kFloat ||
          model.TypeOf(b->rhs->id).base == glsl::BaseType::kFloat) {
        found = true;
      }
    }
    if (const auto* i = node.As<glsl::IndexExpr>(); i != nullptr && i->index != nullptr) {
      if (model.TypeOf(i->index->id).IsFloating()) found = true;
    }
    return !found;
  });
  return found;
}

}  // namespace shaderport::rules::typing
