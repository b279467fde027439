// webgl/block-layout: `layout(packed)` and `layout(shared)` uniform blocks. WebGL 2
// ("Only std140 layout is supported") rejects them, because their layout would be
// up to the driver; glslang accepts them as GLSL ES 3.00 does.
//
//   layout(shared) uniform B { vec4 v; };   // error: use std140
#include <string>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/block-layout";

void CheckQualifiers(rule::RuleContext& context, const glsl::QualifierList& qualifiers) {
  for (const glsl::Qualifier& qualifier : qualifiers.items) {
    if (qualifier.kind != glsl::QualifierKind::kLayout) continue;
    for (const glsl::LayoutId& id : qualifier.layout_ids) {
      if (id.name.text != "packed" && id.name.text != "shared") continue;
      webgl::ReportError(
          context, kId, id.name.range,
          "'" + id.name.text + "' block layout is not allowed in WebGL; only std140 is");
    }
  }
}

class BlockLayoutRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "A packed or shared block layout (WebGL allows std140 only)",
        "layout(shared) uniform B { vec4 v; };", "", rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    constexpr glsl::NodeKinds kQualified = {glsl::NodeKind::kInterfaceBlock,
                                            glsl::NodeKind::kQualifierDeclaration,
                                            glsl::NodeKind::kVariableDeclaration};
    glsl::ForEachNodeOf(context.Tree(), kQualified, [&](const glsl::Node& node) {
      if (const auto* block = node.As<glsl::InterfaceBlock>()) {
        CheckQualifiers(context, block->qualifiers);
      } else if (const auto* declaration = node.As<glsl::QualifierDeclaration>()) {
        CheckQualifiers(context, declaration->qualifiers);
      } else if (const auto* variable = node.As<glsl::VariableDeclaration>()) {
        CheckQualifiers(context, variable->qualifiers);
      }
    });
  }
};

}  // namespace

const rule::Rule& WebglBlockLayoutRule() {
  static const BlockLayoutRule rule;
  return rule;
}

}  // namespace shaderport::rules
