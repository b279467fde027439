// webgl/struct-in-signature: a struct defined inside a function's parameter list.
// GLSL ES 3.00.6 section 12.10 forbids it and browsers reject it in both GLSL ES
// versions; glslang accepts it. A struct defined in a return type
// (`struct S { float x; } f() {...}`) compiles in Chromium 156, in both versions.
//
//   void f(struct S { float x; } s) {}   // error: define S before f
#include <string>

#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/struct-in-signature";

class StructInSignatureRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "A struct defined in a function's parameter list",
                                     "void f(struct S { float x; } s) {}", "",
                                     rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    for (const glsl::Node* declaration : context.Tree().Root()->declarations) {
      const auto* function = declaration->As<glsl::FunctionDeclaration>();
      if (function == nullptr) continue;
      for (const glsl::ParameterDeclaration* parameter : function->parameters) {
        if (parameter->type == nullptr || parameter->type->struct_def == nullptr) continue;
        webgl::ReportError(context, kId, parameter->type->struct_def->range,
                           "a function parameter's type cannot be a struct definition; define "
                           "the struct before '" +
                               function->name.text + "'");
      }
    }
  }
};

}  // namespace

const rule::Rule& WebglStructInSignatureRule() {
  static const StructInSignatureRule rule;
  return rule;
}

}  // namespace shaderport::rules
