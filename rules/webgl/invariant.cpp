// webgl/invariant: `invariant` where the browser does not allow it.
// - GLSL ES 1.00 (section 4.6.1): only varyings and the built-in outputs and
//   fragment inputs may be invariant; never gl_FrontFacing, uniforms, attributes
//   or plain globals.
// - GLSL ES 3.00 (section 4.6.1): only outputs (vertex `out`, fragment `out`,
//   gl_Position, gl_PointSize, gl_FragDepth), and `#pragma STDGL invariant(all)`
//   only in vertex shaders.
//
//   invariant gl_FrontFacing;   // error in GLSL ES 1.00
#include <string>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/invariant";

bool BuiltinMayBeInvariant(std::string_view name, bool essl100, bool fragment) {
  if (name == "gl_Position" || name == "gl_PointSize") return !fragment;
  if (!fragment) return false;
  // Built-in outputs, and in GLSL ES 1.00 the fragment inputs except gl_FrontFacing.
  if (name == "gl_FragColor" || name == "gl_FragData" || name == "gl_FragDepth" ||
      name == "gl_FragDepthEXT") {
    return true;
  }
  return essl100 && (name == "gl_FragCoord" || name == "gl_PointCoord");
}

bool QualifiersMayBeInvariant(const glsl::QualifierList& qualifiers, bool essl100, bool fragment) {
  (void)fragment;  // the same qualifiers are outputs of either stage
  if (essl100) return qualifiers.Has(glsl::QualifierKind::kVarying);
  return qualifiers.Has(glsl::QualifierKind::kOut) && !qualifiers.Has(glsl::QualifierKind::kIn);
}

void ReportInvariant(rule::RuleContext& context, const SourceRange& range, std::string_view name,
                     bool essl100) {
  webgl::ReportError(context, kId, range,
                     "'" + std::string(name) + "' cannot be qualified as invariant: " +
                         (essl100 ? "GLSL ES 1.00 allows it on varyings and built-in outputs only"
                                  : "GLSL ES 3.00 allows it on shader outputs only"));
}

class InvariantRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "`invariant` on a variable that cannot be invariant",
                                     "invariant gl_FrontFacing;", "", rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const bool essl100 = webgl::IsEssl100(context);
    const bool fragment = webgl::IsFragment(context);
    for (const glsl::PragmaDirective& pragma : context.Preprocessed().pragmas) {
      if (!essl100 && fragment && pragma.text.starts_with("STDGL invariant ( all")) {
        webgl::ReportError(context, kId, pragma.range,
                           "'#pragma STDGL invariant(all)' cannot be used in a GLSL ES 3.00 "
                           "fragment shader");
      }
    }
    for (const glsl::Node* node : context.Tree().Root()->declarations) {
      if (const auto* variable = node->As<glsl::VariableDeclaration>()) {
        if (!variable->qualifiers.Has(glsl::QualifierKind::kInvariant)) continue;
        if (QualifiersMayBeInvariant(variable->qualifiers, essl100, fragment)) continue;
        for (const glsl::Declarator* declarator : variable->declarators) {
          ReportInvariant(context, declarator->name.range, declarator->name.text, essl100);
        }
      } else if (const auto* declaration = node->As<glsl::QualifierDeclaration>()) {
        if (!declaration->qualifiers.Has(glsl::QualifierKind::kInvariant)) continue;
        for (const glsl::Name& name : declaration->names) {
          if (name.text.starts_with("gl_")) {
            if (!BuiltinMayBeInvariant(name.text, essl100, fragment)) {
              ReportInvariant(context, name.range, name.text, essl100);
            }
            continue;
          }
          CheckRedeclared(context, name, essl100, fragment);
        }
      }
    }
  }

 private:
  // `invariant v;` on a user variable: v must be a varying / output declared before.
  static void CheckRedeclared(rule::RuleContext& context, const glsl::Name& name, bool essl100,
                              bool fragment) {
    const glsl::SemanticModel& model = context.Model();
    for (uint32_t id : model.FindSymbols(name.text)) {
      const glsl::Symbol& symbol = model.symbols[id];
      if (symbol.kind != glsl::SymbolKind::kVariable || symbol.declaration == glsl::kNoNode) {
        continue;
      }
      // The declarator's parent declaration holds the qualifiers.
      const glsl::VariableDeclaration* owner = nullptr;
      for (const glsl::Node* node : context.Tree().Root()->declarations) {
        const auto* variable = node->As<glsl::VariableDeclaration>();
        if (variable == nullptr) continue;
        for (const glsl::Declarator* declarator : variable->declarators) {
          if (declarator->id == symbol.declaration) owner = variable;
        }
      }
      if (owner == nullptr) return;
      if (!QualifiersMayBeInvariant(owner->qualifiers, essl100, fragment)) {
        ReportInvariant(context, name.range, name.text, essl100);
      }
      return;
    }
  }
};

}  // namespace

const rule::Rule& WebglInvariantRule() {
  static const InvariantRule rule;
  return rule;
}

}  // namespace shaderport::rules
