// webgl/const-from-variable: in GLSL ES 1.00 code, a local `const` initialised from a
// variable that is not const (a local, a parameter, a uniform). That is not a
// constant expression (GLSL ES 1.00 section 4.3.2) and browsers reject it
// ("assigning non-constant to 'const highp float'"); glslang accepts it for locals.
// Globals and GLSL ES 3.00 code are left to glslang, which rejects them itself.
//
//   void main() { float y = 1.0; const float x = y; }   // error
#include <set>
#include <string>
#include <string_view>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/const-from-variable";

// The variable `name` reads is not const: a local, a parameter or a uniform.
bool ReadsVariable(const glsl::Symbol* symbol) {
  return symbol != nullptr && !symbol->is_const &&
         (symbol->kind == glsl::SymbolKind::kVariable ||
          symbol->kind == glsl::SymbolKind::kParameter);
}

class ConstFromVariableRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "A GLSL ES 1.00 local const read from a variable",
                                     "float y = 1.0; const float x = y;", "",
                                     rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    if (context.Settings().source_version >= 300) return;
    const glsl::TranslationUnit* root = context.Tree().Root();
    if (root == nullptr) return;
    const std::set<const glsl::Node*> globals(root->declarations.begin(), root->declarations.end());
    glsl::ForEachNodeOf(
        context.Tree(), {glsl::NodeKind::kVariableDeclaration}, [&](const glsl::Node& node) {
          const auto& declaration = *node.As<glsl::VariableDeclaration>();
          if (globals.contains(&node) || !declaration.qualifiers.Has(glsl::QualifierKind::kConst))
            return;
          for (const glsl::Declarator* declarator : declaration.declarators) {
            if (declarator->initializer != nullptr) Check(context, *declarator);
          }
        });
  }

 private:
  static void Check(rule::RuleContext& context, const glsl::Declarator& declarator) {
    // `a.length()` is constant whatever `a` is.
    std::set<const glsl::Node*> length_objects;
    glsl::ForEachNodeOf(context.Tree(), *declarator.initializer, {glsl::NodeKind::kCallExpr},
                        [&](const glsl::Node& inner) {
                          const auto& call = *inner.As<glsl::CallExpr>();
                          if (call.call_kind == glsl::CallKind::kMethod && call.object != nullptr)
                            length_objects.insert(call.object);
                        });
    bool reported = false;
    glsl::ForEachNodeOf(context.Tree(), *declarator.initializer, {glsl::NodeKind::kIdentifierExpr},
                        [&](const glsl::Node& inner) {
                          const glsl::Symbol* symbol = webgl::SymbolOf(context, inner);
                          if (reported || length_objects.contains(&inner) || !ReadsVariable(symbol))
                            return;
                          reported = true;
                          webgl::ReportError(
                              context, kId, inner.range,
                              "'" + symbol->name +
                                  "' is not a constant; browsers reject it in the const "
                                  "initializer of '" +
                                  declarator.name.text + "'");
                        });
  }
};

}  // namespace

const rule::Rule& WebglConstFromVariableRule() {
  static const ConstFromVariableRule rule;
  return rule;
}

}  // namespace shaderport::rules
