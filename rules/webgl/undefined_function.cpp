// webgl/undefined-function: a call of a function that is declared but never defined.
// Browsers reject it when compiling the stage ("Function f() called by main() is
// undefined"), from any function with a body, called or not; glslang only when it
// links a whole program. A prototype nobody calls is fine.
//
//   float noise(vec2 p);
//   void main() { gl_FragColor = vec4(noise(vec2(0.0))); }   // error: no body
#include <string>

#include "rules/all_rules.h"
#include "rules/webgl/call_graph.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/undefined-function";

class UndefinedFunctionRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "A call of a function that is declared but never defined",
                                     "float f(float x);\nfloat g() { return f(1.0); }", "",
                                     rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const auto& symbols = context.Model().symbols;
    for (const auto& [caller, calls] : webgl::BuildCallGraph(context)) {
      for (const webgl::Call& call : calls) {
        const glsl::Symbol& callee = symbols[call.callee];
        if (callee.definition != glsl::kNoNode || callee.predeclared) continue;
        webgl::ReportError(context, kId, call.site->callee.range,
                           "'" + callee.name +
                               "' is declared but never defined; browsers reject "
                               "a call of it (from '" +
                               symbols[caller].name + "')");
      }
    }
  }
};

}  // namespace

const rule::Rule& WebglUndefinedFunctionRule() {
  static const UndefinedFunctionRule rule;
  return rule;
}

}  // namespace shaderport::rules
