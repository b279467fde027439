// webgl/interpolation-qualifier: `smooth`, `flat` and `centroid` in GLSL ES 3.00
// belong to the values passed between the stages only: a vertex shader's `out`
// and a fragment shader's `in` variables at global scope. Browsers reject them on
// uniforms, consts, locals, vertex inputs and fragment outputs ("qualifier can only
// be used with in and out variables"); glslang accepts several of those.
//
//   smooth uniform float u;     // error
//   centroid out vec4 color;    // error in a fragment shader
#include <string>
#include <unordered_set>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/interpolation-qualifier";

bool IsInterpolation(glsl::QualifierKind kind) {
  return kind == glsl::QualifierKind::kSmooth || kind == glsl::QualifierKind::kFlat ||
         kind == glsl::QualifierKind::kCentroid;
}

// Where the qualifier is allowed, or why not.
std::string Misuse(const rule::RuleContext& context, const glsl::QualifierList& qualifiers,
                   bool global) {
  if (!global) return "a local variable";
  const bool in = qualifiers.Has(glsl::QualifierKind::kIn);
  const bool out = qualifiers.Has(glsl::QualifierKind::kOut);
  if (webgl::IsFragment(context)) {
    if (in) return {};
    return out ? "a fragment shader's output" : "a variable that is not a fragment input";
  }
  if (out) return {};
  return in ? "a vertex shader's input" : "a variable that is not a vertex output";
}

class InterpolationQualifierRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "smooth, flat or centroid on what is not a value passed between stages",
        "smooth uniform float u;", "", rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    if (webgl::IsEssl100(context)) return;  // reserved words there: glslang rejects them
    std::unordered_set<const glsl::Node*> globals(context.Tree().Root()->declarations.begin(),
                                                  context.Tree().Root()->declarations.end());
    glsl::ForEachNodeOf(context.Tree(), {glsl::NodeKind::kVariableDeclaration},
                        [&](const glsl::Node& node) {
                          const auto& declaration = *node.As<glsl::VariableDeclaration>();
                          Check(context, declaration, globals.contains(&node));
                        });
  }

 private:
  static void Check(rule::RuleContext& context, const glsl::VariableDeclaration& declaration,
                    bool global) {
    for (const glsl::Qualifier& qualifier : declaration.qualifiers.items) {
      if (!IsInterpolation(qualifier.kind)) continue;
      const std::string misuse = Misuse(context, declaration.qualifiers, global);
      if (misuse.empty()) return;
      webgl::ReportError(context, kId, qualifier.range,
                         "'" + std::string(glsl::QualifierSpelling(qualifier.kind)) +
                             "' can only qualify values passed between the stages (a vertex "
                             "shader's 'out', a fragment shader's 'in'), not " +
                             misuse);
      return;
    }
  }
};

}  // namespace

const rule::Rule& WebglInterpolationQualifierRule() {
  static const InterpolationQualifierRule rule;
  return rule;
}

}  // namespace shaderport::rules
