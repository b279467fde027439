// webgl/repeated-layout: two `layout(...)` qualifiers on one GLSL ES 3.00 declaration.
// GLSL ES 3.00 allows one (3.10 and desktop GLSL allow several, which glslang follows);
// browsers reject the second ("The layout qualifier specified multiple times").
//
//   layout(location = 0) layout(location = 1) in vec4 a;   // error
#include <string_view>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/repeated-layout";

const glsl::QualifierList* QualifiersOf(const glsl::Node& node) {
  if (const auto* n = node.As<glsl::VariableDeclaration>()) return &n->qualifiers;
  if (const auto* n = node.As<glsl::QualifierDeclaration>()) return &n->qualifiers;
  if (const auto* n = node.As<glsl::InterfaceBlock>()) return &n->qualifiers;
  if (const auto* n = node.As<glsl::ParameterDeclaration>()) return &n->qualifiers;
  if (const auto* n = node.As<glsl::FunctionDeclaration>()) return &n->qualifiers;
  return nullptr;
}

class RepeatedLayoutRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "Two layout qualifiers on one declaration",
                                     "layout(location = 0) layout(location = 1) in vec4 a;", "",
                                     rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    if (context.Settings().source_version != 300) return;
    glsl::ForEachNodeOf(
        context.Tree(),
        {glsl::NodeKind::kVariableDeclaration, glsl::NodeKind::kQualifierDeclaration,
         glsl::NodeKind::kInterfaceBlock, glsl::NodeKind::kParameterDeclaration,
         glsl::NodeKind::kFunctionDeclaration},
        [&](const glsl::Node& node) {
          const glsl::QualifierList* qualifiers = QualifiersOf(node);
          if (qualifiers == nullptr) return;
          bool seen = false;
          for (const glsl::Qualifier& qualifier : qualifiers->items) {
            if (qualifier.kind != glsl::QualifierKind::kLayout) continue;
            if (seen) {
              webgl::ReportError(context, kId, qualifier.range,
                                 "the layout qualifier is specified more than "
                                 "once; GLSL ES 3.00 allows one per declaration "
                                 "(merge them into one layout(...))");
              return;
            }
            seen = true;
          }
        });
  }
};

}  // namespace

const rule::Rule& WebglRepeatedLayoutRule() {
  static const RepeatedLayoutRule rule;
  return rule;
}

}  // namespace shaderport::rules
