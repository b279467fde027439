// webgl/extension-support: `#extension` lines for extensions the WebGL context does
// not offer (src/model/webgl_context_extensions.def: OES_standard_derivatives exists
// in WebGL 1 only, OVR_multiview2 in WebGL 2 only, and so on) or the page did not
// enable (`--enabled-extensions`), and `all` with `enable` or `require`. `require` of a missing
// extension and `all : enable|require` are errors in browsers, `enable` and `warn` a warning;
// either way the extension's functions and variables stay unavailable (`check` hides such lines
// from glslang).
//
//   #extension GL_OES_standard_derivatives : require   // error in a WebGL 2 context
#include <string>

#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/extension-support";

class ExtensionSupportRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "An #extension the WebGL context does not offer",
                                     "#extension GL_OVR_multiview2 : require  // in WebGL 1", "",
                                     rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const bool webgl2 = webgl::InWebgl2(context);
    for (const glsl::ExtensionDirective& directive : context.Preprocessed().extensions) {
      const std::string& name = directive.name;
      const std::string& behavior = directive.behavior;
      if (name == "all") {
        if (behavior == "enable" || behavior == "require") {
          webgl::ReportError(
              context, kId, directive.range,
              "'#extension all' takes only 'warn' or 'disable', not '" + behavior + "'");
        }
        continue;
      }
      const model::Target target = context.Settings().target;
      if (behavior == "disable" ||
          model::ExtensionAvailable(name, target, context.Settings().extensions)) {
        continue;
      }
      const std::string message =
          model::ContextOffersExtension(name, target)
              ? "'" + name +
                    "' is not enabled by the page (--enabled-extensions); its functions and "
                    "variables are not there"
              : "'" + name + "' is not an extension a " + (webgl2 ? "WebGL 2" : "WebGL 1") +
                    " context offers; its functions and variables are not there";
      if (behavior == "require") {
        webgl::ReportError(context, kId, directive.range, message);
      } else {
        context.Report(
            MakeDiagnostic(Severity::kWarning, std::string(kId), directive.range, message));
      }
    }
  }
};

}  // namespace

const rule::Rule& WebglExtensionSupportRule() {
  static const ExtensionSupportRule rule;
  return rule;
}

}  // namespace shaderport::rules
