// webgl/missing-main: a stage without a `void main()` body. Browsers reject it when
// compiling the stage ("Missing main()"); glslang only when it links the program.
// ShaderToy code gets its main() from the site, and Common code has none of its own.
//
//   void mainImage(out vec4 c, in vec2 p) { ... }   // error in a plain WebGL shader
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/missing-main";

class MissingMainRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "A shader stage without a main() function",
                                     "void entry() { gl_FragColor = vec4(1.0); }", "",
                                     rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    if (context.Settings().behind_site_header) return;
    for (const glsl::Node* node : context.Tree().Root()->declarations) {
      const auto* function = node->As<glsl::FunctionDeclaration>();
      if (function != nullptr && function->body != nullptr && function->name.text == "main") {
        return;
      }
    }
    const SourceFile& file = context.File();
    webgl::ReportError(context, kId, {file.Id(), 0, 0},
                       "the shader has no main() function; browsers reject it (\"Missing "
                       "main()\")");
  }
};

}  // namespace

const rule::Rule& WebglMissingMainRule() {
  static const MissingMainRule rule;
  return rule;
}

}  // namespace shaderport::rules
