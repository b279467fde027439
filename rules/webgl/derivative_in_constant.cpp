// webgl/derivative-in-constant: dFdx, dFdy or fwidth in a `const` initializer.
// Derivatives are never constant expressions (GLSL ES 3.00 section 4.3.3) and browsers
// reject the initializer ("assigning non-constant to 'const float'"); glslang folds
// the derivative of a constant to 0 and accepts it.
//
//   const float d = dFdx(1.0);   // error
#include <string>
#include <string_view>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/derivative-in-constant";

bool IsDerivative(std::string_view name) {
  return name == "dFdx" || name == "dFdy" || name == "fwidth";
}

class DerivativeInConstantRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "A derivative in a const initializer",
                                     "const float d = dFdx(1.0);", "", rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    glsl::ForEachNodeOf(
        context.Tree(), {glsl::NodeKind::kVariableDeclaration}, [&](const glsl::Node& node) {
          const auto& declaration = *node.As<glsl::VariableDeclaration>();
          if (!declaration.qualifiers.Has(glsl::QualifierKind::kConst)) return;
          for (const glsl::Declarator* declarator : declaration.declarators) {
            if (declarator->initializer == nullptr) continue;
            glsl::ForEachNodeOf(context.Tree(), *declarator->initializer,
                                {glsl::NodeKind::kCallExpr}, [&](const glsl::Node& inner) {
                                  const auto& call = *inner.As<glsl::CallExpr>();
                                  if (call.call_kind != glsl::CallKind::kFunction ||
                                      !IsDerivative(call.callee.text)) {
                                    return;
                                  }
                                  webgl::ReportError(context, kId, call.callee.range,
                                                     "'" + call.callee.text +
                                                         "' is never a constant expression; "
                                                         "browsers reject it in the const "
                                                         "initializer of '" +
                                                         declarator->name.text + "'");
                                });
          }
        });
  }
};

}  // namespace

const rule::Rule& WebglDerivativeInConstantRule() {
  static const DerivativeInConstantRule rule;
  return rule;
}

}  // namespace shaderport::rules
