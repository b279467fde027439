// webgl/loop-index-write: a for-loop index changed inside the loop's body.
// GLSL ES 1.00 Appendix A (enforced by WebGL for GLSL ES 1.00 code) makes the
// index read-only in the body: no assignment, ++/--, or out/inout argument.
//
//   for (int i = 0; i < 4; i++) { i += 1; }   // error
#include <string>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/appendix_a.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/loop-index-write";

// The parameter declarations of the user function a call resolves to.
const glsl::FunctionDeclaration* CalledFunction(const rule::RuleContext& context,
                                                const glsl::CallExpr& call) {
  const glsl::Symbol* symbol = webgl::SymbolOf(context, call);
  if (symbol == nullptr || symbol->kind != glsl::SymbolKind::kFunction) return nullptr;
  const uint32_t node = symbol->declaration;
  if (node == glsl::kNoNode || node >= context.Tree().NodeCount()) return nullptr;
  return context.Tree().NodeAt(node).As<glsl::FunctionDeclaration>();
}

class LoopIndexWriteRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "A for-loop index written inside the loop body",
                                     "for (int i = 0; i < 4; i++) { i += 1; }", "",
                                     rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    if (!webgl::AppendixAApplies(context)) return;
    glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, uint32_t) {
      const auto* loop = node.As<glsl::ForStatement>();
      if (loop == nullptr || loop->body == nullptr) return true;
      const auto* declaration =
          loop->init != nullptr ? loop->init->As<glsl::VariableDeclaration>() : nullptr;
      if (declaration == nullptr || declaration->declarators.size() != 1) return true;
      const uint32_t index = context.Model().SymbolAt(declaration->declarators[0]->id);
      if (index != glsl::kNoSymbol) CheckBody(context, *loop->body, index);
      return true;
    });
  }

 private:
  static bool IsIndex(const rule::RuleContext& context, const glsl::Expr* expr, uint32_t index) {
    expr = webgl::Unparenthesized(expr);
    return expr != nullptr && expr->kind == glsl::NodeKind::kIdentifierExpr &&
           context.Model().SymbolAt(expr->id) == index;
  }

  static void Report(rule::RuleContext& context, const glsl::Expr& where, uint32_t index) {
    webgl::ReportError(context, kId, where.range,
                       "the loop index '" + context.Model().symbols[index].name +
                           "' cannot be changed inside the loop body in GLSL ES 1.00 "
                           "(Appendix A)");
  }

  static void CheckBody(rule::RuleContext& context, const glsl::Node& body, uint32_t index) {
    glsl::VisitPreorder(context.Tree(), body, [&](const glsl::Node& node, uint32_t) {
      if (const auto* assignment = node.As<glsl::AssignmentExpr>()) {
        if (IsIndex(context, assignment->lhs, index)) Report(context, *assignment->lhs, index);
      } else if (const auto* unary = node.As<glsl::UnaryExpr>()) {
        if (unary->op >= glsl::UnaryOp::kPreIncrement && IsIndex(context, unary->operand, index)) {
          Report(context, *unary->operand, index);
        }
      } else if (const auto* call = node.As<glsl::CallExpr>()) {
        const glsl::FunctionDeclaration* function = CalledFunction(context, *call);
        if (function == nullptr) return true;
        for (size_t i = 0; i < call->arguments.size() && i < function->parameters.size(); ++i) {
          const glsl::QualifierList& qualifiers = function->parameters[i]->qualifiers;
          const bool writes = qualifiers.Has(glsl::QualifierKind::kOut) ||
                              qualifiers.Has(glsl::QualifierKind::kInOut);
          if (writes && IsIndex(context, call->arguments[i], index)) {
            Report(context, *call->arguments[i], index);
          }
        }
      }
      return true;
    });
  }
};

}  // namespace

const rule::Rule& WebglLoopIndexWriteRule() {
  static const LoopIndexWriteRule rule;
  return rule;
}

}  // namespace shaderport::rules
