// webgl/const-initializer: a `const` initializer that reads a variable that is not
// `const`, or calls dFdx, dFdy or fwidth. Neither is a constant expression (GLSL ES
// section 4.3.3) and browsers reject the initializer ("assigning non-constant to
// 'const float'"); glslang accepts some of them (a GLSL ES 1.00 local read from a
// local, the derivative of a constant, which it folds to 0).
//
//   float y = 1.0; const float x = y;   // error
//   const float d = dFdx(1.0);          // error
#include <string>
#include <string_view>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/const-initializer";

bool IsDerivative(std::string_view name) {
  return name == "dFdx" || name == "dFdy" || name == "fwidth";
}

class ConstInitializerRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "A const initializer that is not a constant expression",
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
            bool reported = false;
            glsl::ForEachNodeOf(context.Tree(), *declarator->initializer,
                                {glsl::NodeKind::kIdentifierExpr}, [&](const glsl::Node& inner) {
                                  const glsl::Symbol* symbol = webgl::SymbolOf(context, inner);
                                  if (reported || symbol == nullptr || symbol->is_const ||
                                      (symbol->kind != glsl::SymbolKind::kVariable &&
                                       symbol->kind != glsl::SymbolKind::kParameter)) {
                                    return;
                                  }
                                  reported = true;
                                  webgl::ReportError(
                                      context, kId, inner.range,
                                      "'" + symbol->name +
                                          "' is not a constant; browsers reject it in the const "
                                          "initializer of '" +
                                          declarator->name.text + "'");
                                });
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

const rule::Rule& WebglConstInitializerRule() {
  static const ConstInitializerRule rule;
  return rule;
}

}  // namespace shaderport::rules
