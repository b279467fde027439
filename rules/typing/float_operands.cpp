#include "rules/typing/float_operands.h"

#include "glsl/sema/operator_typing.h"
#include "glsl/syntax/visit.h"
#include "rules/typing/typing_support.h"

namespace shaderport::rules::typing {
namespace {

using glsl::Type;

void ConvertOperand(const rule::RuleContext& context, const glsl::Expr& e,
                    const std::string& float_type, std::vector<FixIt>& fixes) {
  if (float_type.empty()) return;
  if (const glsl::LiteralExpr* literal = AsIntLiteral(&e)) {
    const SourceRange range = WrittenRange(context, *literal);
    if (auto spelling = FloatSpelling(*literal); spelling && InThisFile(context, range)) {
      fixes.push_back({range, *spelling});
      return;
    }
  }
  for (FixIt& fix : WrapInCall(context, e, float_type)) fixes.push_back(std::move(fix));
}

}  // namespace

FloatOperands ClassifyModOperands(const rule::RuleContext& context, const glsl::Expr& lhs,
                                  const glsl::Expr& rhs, bool compound) {
  const glsl::SemanticModel& model = context.Model();
  const Type& lt = model.TypeOf(lhs.id);
  const Type& rt = model.TypeOf(rhs.id);
  FloatOperands result;
  if (!lt.IsNumeric() || !rt.IsNumeric()) return result;
  if (lt.base != glsl::BaseType::kFloat && rt.base != glsl::BaseType::kFloat) return result;
  result.floating = true;
  result.lhs_type = model.Spell(lt);
  result.rhs_type = model.Spell(rt);
  const Type lf = lt.base == glsl::BaseType::kInt ? glsl::IntToFloat(lt) : lt;
  const Type rf = rt.base == glsl::BaseType::kInt ? glsl::IntToFloat(rt) : rt;
  if (lf.base != glsl::BaseType::kFloat || rf.base != glsl::BaseType::kFloat) {
    result.why_not =
        "mod() takes floats, not " + model.Spell(lf.base == glsl::BaseType::kFloat ? rt : lt);
    return result;
  }
  if (lf.IsMatrix() || rf.IsMatrix()) {
    result.why_not = "mod() takes no matrices";
    return result;
  }
  if (!(lf == rf || rf == Type::Float())) {
    result.why_not = "mod() has no overload for (" + model.Spell(lf) + ", " + model.Spell(rf) + ")";
    return result;
  }
  if (compound && lt.base != glsl::BaseType::kFloat) {
    result.why_not = "the result of mod() is a float but '" + result.lhs_type + "' is not";
    return result;
  }
  result.fixable = true;
  if (lt.base == glsl::BaseType::kInt) result.lhs_float = model.Spell(lf);
  if (rt.base == glsl::BaseType::kInt) result.rhs_float = model.Spell(rf);
  return result;
}

void AppendOperandFixes(const rule::RuleContext& context, const FloatOperands& operands,
                        const glsl::Expr& lhs, const glsl::Expr& rhs, std::vector<FixIt>& fixes) {
  ConvertOperand(context, lhs, operands.lhs_float, fixes);
  ConvertOperand(context, rhs, operands.rhs_float, fixes);
}

bool IsSideEffectFree(const glsl::Expr& e) {
  bool pure = true;
  glsl::VisitPreorder(e, [&](const glsl::Node& node, uint32_t) {
    if (node.kind == glsl::NodeKind::kCallExpr || node.kind == glsl::NodeKind::kAssignmentExpr ||
        node.kind == glsl::NodeKind::kErrorExpr) {
      pure = false;
    } else if (const auto* u = node.As<glsl::UnaryExpr>()) {
      if (u->op != glsl::UnaryOp::kPlus && u->op != glsl::UnaryOp::kMinus &&
          u->op != glsl::UnaryOp::kNot && u->op != glsl::UnaryOp::kBitNot) {
        pure = false;
      }
    }
    return pure;
  });
  return pure;
}

}  // namespace shaderport::rules::typing
