// webgl/extension-placement: an `#extension` line after the first token that is not
// a preprocessor directive. Browsers reject it in GLSL ES 3.00 and in every shader of
// a WebGL 2 context, and warn in GLSL ES 1.00 under WebGL 1 (unless its behaviour is
// `disable`: an error there too); glslang lets it pass.
// ShaderToy code always comes after the site's header (`precision highp float;` and
// its uniforms), so an `#extension` line in a pass or in Common is always too late.
//
//   precision mediump float;
//   #extension GL_OES_standard_derivatives : enable   // error in WebGL 2
#include <string>

#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/extension-placement";

// True when a token that is not a directive comes before `directive`. Files are
// preprocessed in order (Common, then the user's file), so a token of another file
// comes first when the directive is in the user's file.
bool AfterFirstToken(const rule::RuleContext& context, const SourceRange& directive) {
  for (const glsl::PpToken& token : context.Preprocessed().tokens) {
    if (token.kind == glsl::TokenKind::kEndOfFile) break;
    if (token.expansion.file != directive.file) {
      if (directive.file == context.File().Id()) return true;
      continue;
    }
    return token.expansion.begin < directive.begin;
  }
  return false;
}

class ExtensionPlacementRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "An #extension line after the first statement or declaration",
        "precision mediump float;\n#extension GL_OES_standard_derivatives : enable", "",
        rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const bool always_error = !webgl::IsEssl100(context) || webgl::InWebgl2(context);
    for (const glsl::ExtensionDirective& directive : context.Preprocessed().extensions) {
      // A late 'disable' is an error even where other late lines only warn.
      const bool error = always_error || directive.behavior == "disable";
      const bool site_header = context.Settings().behind_site_header;
      if (!site_header && !AfterFirstToken(context, directive.range)) continue;
      std::string message = "'#extension " + directive.name +
                            "' must come before any code that is not a "
                            "preprocessor directive";
      std::string note = site_header ? "ShaderToy compiles every pass after its own header "
                                       "(precision and uniform declarations), so no #extension "
                                       "line in a pass or in Common can come first"
                                     : std::string();
      if (error) {
        webgl::ReportError(context, kId, directive.range, std::move(message), std::move(note));
        continue;
      }
      Diagnostic warning = MakeDiagnostic(Severity::kWarning, std::string(kId), directive.range,
                                          message + " (WebGL 1 browsers only warn)");
      context.Report(std::move(warning));
    }
  }
};

}  // namespace

const rule::Rule& WebglExtensionPlacementRule() {
  static const ExtensionPlacementRule rule;
  return rule;
}

}  // namespace shaderport::rules
