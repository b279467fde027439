// webgl/loop-form: loops outside GLSL ES 1.00 Appendix A, which WebGL enforces for
// GLSL ES 1.00 code: no while or do-while, and every for loop of the form
//   for (int|float i = constant; i relop constant; i++ | i-- | ++i | --i | i += c | i -= c)
// glslang accepts any loop; browsers reject the shader.
//
//   while (i < 3) { ... }               // error
//   for (int i = 0; i < n; i++) { ... } // error when n is a uniform
#include <string>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/appendix_a.h"
#include "rules/webgl/constant_expression.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/loop-form";
constexpr std::string_view kForm =
    "GLSL ES 1.00 in WebGL allows only 'for (int i = constant; i < constant; i++)' loops "
    "(Appendix A)";

bool IsRelational(glsl::BinaryOp op) {
  return op == glsl::BinaryOp::kLess || op == glsl::BinaryOp::kGreater ||
         op == glsl::BinaryOp::kLessEqual || op == glsl::BinaryOp::kGreaterEqual ||
         op == glsl::BinaryOp::kEqual || op == glsl::BinaryOp::kNotEqual;
}

class LoopFormChecker {
 public:
  explicit LoopFormChecker(rule::RuleContext& context) : context_(context) {}

  void Check(const glsl::ForStatement& loop) {
    const uint32_t index = CheckInit(loop);
    if (index == glsl::kNoSymbol) return;
    CheckCondition(loop, index);
    CheckIncrement(loop, index);
  }

 private:
  void Error(const SourceRange& range, const std::string& message) {
    webgl::ReportError(context_, kId, range, message, std::string(kForm));
  }

  bool Constant(const glsl::Expr* expr) {
    return expr != nullptr && webgl::IsConstantExpression(context_.Model(), *expr, {100});
  }

  bool IsIndex(const glsl::Expr* expr, uint32_t index) {
    expr = webgl::Unparenthesized(expr);
    return expr != nullptr && expr->kind == glsl::NodeKind::kIdentifierExpr &&
           context_.Model().SymbolAt(expr->id) == index;
  }

  uint32_t CheckInit(const glsl::ForStatement& loop) {
    const auto* declaration =
        loop.init != nullptr ? loop.init->As<glsl::VariableDeclaration>() : nullptr;
    if (declaration == nullptr || declaration->declarators.size() != 1 ||
        declaration->declarators[0]->initializer == nullptr ||
        !declaration->declarators[0]->array.empty()) {
      Error(loop.init != nullptr && loop.init->HasTokens() ? loop.init->range : loop.range,
            "the for loop must declare and initialise exactly one loop index");
      return glsl::kNoSymbol;
    }
    const glsl::Declarator& declarator = *declaration->declarators[0];
    const uint32_t index = context_.Model().SymbolAt(declarator.id);
    if (index == glsl::kNoSymbol) return glsl::kNoSymbol;
    const glsl::Type& type = context_.Model().symbols[index].type;
    if (!type.IsUnknown() && !(type == glsl::Type::Int() || type == glsl::Type::Float())) {
      Error(declarator.name.range,
            "the loop index '" + declarator.name.text + "' must be an int or a float scalar");
    }
    if (!Constant(declarator.initializer)) {
      Error(declarator.initializer->range, "the loop index '" + declarator.name.text +
                                               "' must be initialised with a constant expression");
    }
    return index;
  }

  void CheckCondition(const glsl::ForStatement& loop, uint32_t index) {
    const auto* condition = loop.condition != nullptr ? loop.condition->As<glsl::Expr>() : nullptr;
    const auto* binary =
        condition != nullptr ? webgl::Unparenthesized(condition)->As<glsl::BinaryExpr>() : nullptr;
    if (binary == nullptr || !IsRelational(binary->op) || !IsIndex(binary->lhs, index)) {
      Error(loop.condition != nullptr ? loop.condition->range : loop.range,
            "the loop condition must compare the loop index with a constant expression");
      return;
    }
    if (!Constant(binary->rhs)) {
      Error(binary->rhs->range, "the loop index cannot be compared with a non-constant expression");
    }
  }

  void CheckIncrement(const glsl::ForStatement& loop, uint32_t index) {
    const glsl::Expr* increment = webgl::Unparenthesized(loop.increment);
    bool ok = false;
    if (increment == nullptr) {
    } else if (const auto* unary = increment->As<glsl::UnaryExpr>()) {
      ok = unary->op >= glsl::UnaryOp::kPreIncrement && IsIndex(unary->operand, index);
    } else if (const auto* assignment = increment->As<glsl::AssignmentExpr>()) {
      const bool op_ok =
          assignment->op == glsl::AssignOp::kAdd || assignment->op == glsl::AssignOp::kSub;
      ok = op_ok && IsIndex(assignment->lhs, index);
      if (ok && !Constant(assignment->rhs)) {
        Error(assignment->rhs->range,
              "the loop index cannot be modified by a non-constant expression");
        return;
      }
    }
    if (!ok) {
      Error(increment != nullptr ? increment->range : loop.range,
            "the loop expression must be i++, i--, ++i, --i, i += constant or i -= constant");
    }
  }

  rule::RuleContext& context_;
};

class LoopFormRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "A loop outside GLSL ES 1.00 Appendix A (while, do-while, non-constant for bounds)",
        "for (int i = 0; i < n; i++) {}  // n a uniform", "", rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    if (!webgl::AppendixAApplies(context)) return;
    LoopFormChecker checker(context);
    glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, uint32_t) {
      if (const auto* loop = node.As<glsl::ForStatement>()) checker.Check(*loop);
      if (node.kind == glsl::NodeKind::kWhileStatement ||
          node.kind == glsl::NodeKind::kDoWhileStatement) {
        const bool is_while = node.kind == glsl::NodeKind::kWhileStatement;
        webgl::ReportError(context, kId, node.range,
                           std::string(is_while ? "while" : "do-while") +
                               " loops are not allowed in GLSL ES 1.00 in WebGL",
                           std::string(kForm));
      }
      return true;
    });
  }
};

}  // namespace

const rule::Rule& WebglLoopFormRule() {
  static const LoopFormRule rule;
  return rule;
}

}  // namespace shaderport::rules
