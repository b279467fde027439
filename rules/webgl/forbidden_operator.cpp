// webgl/forbidden-operator: operators WebGL disallows on some operand types.
// - `?:` on arrays or structs: GLSL ES 1.00 (sections 5.2, 5.7) has no such
//   operator, and WebGL 2 (spec section 5.26) keeps the ban for GLSL ES 3.00;
//   WebGL 2 also forbids `?:` on void.
// - `,` with a void, array or struct-containing-array operand (WebGL 2 section 5.26).
// glslang follows plain GLSL ES 3.00 and accepts both.
// - unary `+` on anything but int, uint and float scalars, vectors and matrices (a
//   struct, bool, bvec, array or sampler): GLSL ES 1.00 and 3.00 section 5.9 define it
//   on numbers only; browsers reject it ("wrong operand type"), glslang lets `+`
//   through unchecked (it rejects `-` on the same operands).
//
//   S s = b ? s1 : s2;          // error: ternary on a struct
//   float a[2] = (x, arr);      // error in WebGL 2: sequence on an array
//   S t = +s;                   // error: unary plus on a struct
#include <string>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/forbidden-operator";

bool NotInSequence(const glsl::SemanticModel& model, const glsl::Type& type) {
  return type.IsArray() || type.IsVoid() ||
         (type.base == glsl::BaseType::kStruct && webgl::StructContainsArray(model, type));
}

class ForbiddenOperatorRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId,
        "`?:` on arrays, structs or void, `,` on void, arrays or structs with arrays, or unary "
        "`+` on what is not a number",
        "S s = b ? s1 : s2;", "", rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const bool strict_ternary = webgl::IsEssl100(context) || webgl::InWebgl2(context);
    // Only the two kinds are looked at: the test stays inline in the walk, the rest not.
    constexpr glsl::NodeKinds kOperators = {
        glsl::NodeKind::kConditionalExpr, glsl::NodeKind::kBinaryExpr, glsl::NodeKind::kUnaryExpr};
    glsl::ForEachNodeOf(context.Tree(), kOperators, [&](const glsl::Node& node) {
      if (node.kind == glsl::NodeKind::kUnaryExpr) {
        CheckUnaryPlus(context, *node.As<glsl::UnaryExpr>());
      } else if (node.kind == glsl::NodeKind::kConditionalExpr) {
        CheckConditional(context, *node.As<glsl::ConditionalExpr>(), strict_ternary);
      } else if (node.As<glsl::BinaryExpr>()->op == glsl::BinaryOp::kComma) {
        CheckSequence(context, *node.As<glsl::BinaryExpr>());
      }
    });
  }

 private:
  [[gnu::noinline]] static void CheckConditional(rule::RuleContext& context,
                                                 const glsl::ConditionalExpr& conditional,
                                                 bool strict_ternary) {
    if (conditional.if_true == nullptr) return;
    const glsl::Type& type = context.Model().TypeOf(conditional.if_true->id);
    const char* what = nullptr;
    if (strict_ternary && type.IsArray()) what = "arrays";
    if (strict_ternary && type.base == glsl::BaseType::kStruct && !type.IsArray()) {
      what = "structs";
    }
    if (webgl::InWebgl2(context) && type.IsVoid()) what = "void";
    if (what != nullptr) {
      webgl::ReportError(context, kId, conditional.range,
                         std::string("the ternary operator '?:' is not allowed on ") + what +
                             " in WebGL; use an if statement");
    }
  }

  [[gnu::noinline]] static void CheckUnaryPlus(rule::RuleContext& context,
                                               const glsl::UnaryExpr& unary) {
    if (unary.op != glsl::UnaryOp::kPlus || unary.operand == nullptr) return;
    const glsl::Type& type = context.Model().TypeOf(unary.operand->id);
    const char* what = nullptr;
    if (type.IsArray()) {
      what = "an array";
    } else if (type.base == glsl::BaseType::kStruct) {
      what = "a struct";
    } else if (type.base == glsl::BaseType::kBool) {
      what = type.IsScalar() ? "a bool" : "a bool vector";
    } else if (type.base == glsl::BaseType::kSampler) {
      what = "a sampler";
    }
    if (what == nullptr) return;
    webgl::ReportError(context, kId, unary.range,
                       std::string("unary '+' is defined on int, uint and float scalars, vectors "
                                   "and matrices, not on ") +
                           what + "; browsers reject it (\"wrong operand type\")");
  }

  [[gnu::noinline]] static void CheckSequence(rule::RuleContext& context,
                                              const glsl::BinaryExpr& binary) {
    if (!webgl::InWebgl2(context)) return;
    const glsl::SemanticModel& model = context.Model();
    for (const glsl::Expr* operand : {binary.lhs, binary.rhs}) {
      if (operand == nullptr || !NotInSequence(model, model.TypeOf(operand->id))) continue;
      webgl::ReportError(context, kId, binary.op_range,
                         "the sequence operator ',' is not allowed on void, arrays or structs "
                         "containing arrays in WebGL 2");
      break;
    }
  }
};

}  // namespace

const rule::Rule& WebglForbiddenOperatorRule() {
  static const ForbiddenOperatorRule rule;
  return rule;
}

}  // namespace shaderport::rules
