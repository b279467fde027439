// webgl/void-parameter: `void` as the type of one parameter among several, as in
// `void f(out void, in vec2);`. Browsers accept `void` only as the whole parameter list,
// `f(void)` ("'void' : cannot be a parameter type except for '(void)'"); glslang rejects
// a named `void` parameter and one after the first, but accepts an unnamed first one.
//
//   void mainImage(out void, in vec2);   // error: the first parameter is 'void'
#include <string>

#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/void-parameter";

class VoidParameterRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "'void' as one parameter among several",
                                     "void f(out void, in vec2);", "", rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    for (const glsl::Node* declaration : context.Tree().Root()->declarations) {
      const auto* function = declaration->As<glsl::FunctionDeclaration>();
      if (function == nullptr || function->parameters.size() < 2) continue;
      // Only the case glslang lets through: the first parameter, unnamed.
      const glsl::ParameterDeclaration* first = function->parameters.front();
      if (first->type == nullptr || first->type->name.text != "void" || !first->name.text.empty() ||
          !first->array.empty()) {
        continue;
      }
      webgl::ReportError(context, kId, first->range,
                         "'void' cannot be a parameter type except for the whole list '(void)'; "
                         "'" +
                             function->name.text + "' has " +
                             std::to_string(function->parameters.size()) + " parameters");
    }
  }
};

}  // namespace

const rule::Rule& WebglVoidParameterRule() {
  static const VoidParameterRule rule;
  return rule;
}

}  // namespace shaderport::rules
