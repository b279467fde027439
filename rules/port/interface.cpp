// port/interface: the GLSL ES 1.00 storage qualifiers `attribute` and `varying`,
// which GLSL ES 3.00 reserves, become `in` and `out`.
//
// Before (vertex):                After:
//   attribute vec3 position;        in vec3 position;
//   varying vec2 uv;                out vec2 uv;
// Before (fragment):              After:
//   varying vec2 uv;                in vec2 uv;
#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/port/port_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "port/interface";

class InterfaceRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "Replace `attribute` and `varying` with `in` and `out`",
                                     "attribute vec3 position;\nvarying vec2 uv;  // vertex shader",
                                     "in vec3 position;\nout vec2 uv;  // vertex shader",
                                     rule::RuleScope::kPort};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const bool vertex = context.Settings().stage == model::Stage::kVertex;
    glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, uint32_t) {
      const glsl::QualifierList* qualifiers = nullptr;
      if (const auto* variable = node.As<glsl::VariableDeclaration>()) {
        qualifiers = &variable->qualifiers;
      } else if (const auto* bare = node.As<glsl::QualifierDeclaration>()) {
        qualifiers = &bare->qualifiers;
      }
      if (qualifiers == nullptr) return !node.IsExpr();
      for (const auto& qualifier : qualifiers->items) {
        Check(context, qualifier, vertex);
      }
      return true;
    });
  }

 private:
  static void Check(rule::RuleContext& context, const glsl::Qualifier& qualifier, bool vertex) {
    if (qualifier.kind != glsl::QualifierKind::kAttribute &&
        qualifier.kind != glsl::QualifierKind::kVarying) {
      return;
    }
    if (!webgl2::InThisFile(context, qualifier.range)) return;
    const bool attribute = qualifier.kind == glsl::QualifierKind::kAttribute;
    const std::string_view old_word = attribute ? "attribute" : "varying";
    if (attribute && !vertex) {
      // Already an error in GLSL ES 1.00: nothing sensible to port it to.
      context.Report(webgl2::MakeDiagnostic(kId, Severity::kError, qualifier.range,
                                            "'attribute' is only allowed in vertex shaders"));
      return;
    }
    const std::string new_word = attribute ? "in" : (vertex ? "out" : "in");
    auto diagnostic = webgl2::MakeDiagnostic(
        kId, Severity::kWarning, qualifier.range,
        "'" + std::string(old_word) + "' is reserved in GLSL ES 3.00; use '" + new_word + "'");
    diagnostic.fixes.push_back(webgl2::Replace(qualifier.range, new_word));
    context.Report(std::move(diagnostic));
  }
};

}  // namespace

const rule::Rule& PortInterfaceRule() {
  static const InterfaceRule rule;
  return rule;
}

}  // namespace shaderport::rules
