// webgl/parameter-redefinition: a GLSL ES 1.00 function body that declares, at its
// outermost level, a variable named like one of the function's parameters. Browsers
// reject it ("'k' : redefinition"): ANGLE gives the parameters and the body one scope
// in both GLSL ES versions. glslang does the same for GLSL ES 3.00 only (its own
// Test/100scope.vert takes the GLSL ES 1.00 case), so the rule looks at 1.00 code.
//
//   int f(int k) { int k = k + 3; return k; }   // error: 'k' redefined
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/parameter-redefinition";

class ParameterRedefinitionRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "A GLSL ES 1.00 function body redeclaring a parameter",
                                     "int f(int k) { int k = k + 3; return k; }", "",
                                     rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    if (!webgl::IsEssl100(context)) return;
    for (const glsl::Node* node : context.Tree().Root()->declarations) {
      const auto* function = node->As<glsl::FunctionDeclaration>();
      if (function == nullptr || function->body == nullptr) continue;
      for (const glsl::Node* statement : function->body->statements) {
        const auto* declaration = statement->As<glsl::VariableDeclaration>();
        if (declaration == nullptr) continue;
        for (const glsl::Declarator* declarator : declaration->declarators) {
          if (Names(*function, declarator->name.text)) {
            webgl::ReportError(context, kId, declarator->name.range,
                               "'" + declarator->name.text +
                                   "' is a parameter of the function: its body may not declare "
                                   "it again; browsers reject it (\"redefinition\")");
          }
        }
      }
    }
  }

 private:
  static bool Names(const glsl::FunctionDeclaration& function, const std::string& name) {
    for (const glsl::ParameterDeclaration* parameter : function.parameters) {
      if (parameter != nullptr && parameter->name.text == name) return true;
    }
    return false;
  }
};

}  // namespace

const rule::Rule& WebglParameterRedefinitionRule() {
  static const ParameterRedefinitionRule rule;
  return rule;
}

}  // namespace shaderport::rules
