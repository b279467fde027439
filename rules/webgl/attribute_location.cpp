// webgl/attribute-location: a GLSL ES 3.00 vertex input at `layout(location = N)`
// with N at or past MAX_VERTEX_ATTRIBS (16 in Chromium). Browsers reject it when
// compiling ("Attribute location out of range"); glslang accepts it. Only the first
// location is checked, as Chromium does: a mat4 at location 13 compiles.
//
//   layout(location = 16) in vec4 extra;   // error: 0 to 15
#include <string>

#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/attribute-location";
constexpr int64_t kMaxVertexAttribs = 16;

class AttributeLocationRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "A vertex input location at or past MAX_VERTEX_ATTRIBS",
                                     "layout(location = 16) in vec4 extra;", "",
                                     rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    if (webgl::IsEssl100(context) || webgl::IsFragment(context)) return;
    for (const glsl::Node* node : context.Tree().Root()->declarations) {
      const auto* declaration = node->As<glsl::VariableDeclaration>();
      if (declaration == nullptr || !declaration->qualifiers.Has(glsl::QualifierKind::kIn)) {
        continue;
      }
      const auto location = webgl::LayoutLocation(declaration->qualifiers);
      if (!location || *location < kMaxVertexAttribs || declaration->declarators.empty()) {
        continue;
      }
      webgl::ReportError(context, kId, declaration->declarators.front()->name.range,
                         "vertex input location " + std::to_string(*location) +
                             " is out of range: WebGL has 16 attribute locations (0 to 15)");
    }
  }
};

}  // namespace

const rule::Rule& WebglAttributeLocationRule() {
  static const AttributeLocationRule rule;
  return rule;
}

}  // namespace shaderport::rules
