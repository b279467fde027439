// webgl/frag-data-and-color: a GLSL ES 1.00 fragment shader that uses both
// gl_FragColor and gl_FragData. GLSL ES 1.00 section 7.2 forbids writing both;
// browsers reject any static use of the two, glslang accepts it.
//
//   gl_FragColor = c;
//   gl_FragData[0] = c;   // error: pick one
#include <string>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/frag-data-and-color";

class FragDataAndColorRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "A fragment shader uses both gl_FragColor and gl_FragData",
        "gl_FragColor = c;\ngl_FragData[0] = c;", "", rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    if (!webgl::IsEssl100(context) || !webgl::IsFragment(context)) return;
    const glsl::IdentifierExpr* color = nullptr;
    const glsl::IdentifierExpr* data = nullptr;
    glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, uint32_t) {
      if (const auto* identifier = node.As<glsl::IdentifierExpr>()) {
        if (identifier->name == "gl_FragColor" && color == nullptr) color = identifier;
        if (identifier->name == "gl_FragData" && data == nullptr) data = identifier;
      }
      return true;
    });
    if (color == nullptr || data == nullptr) return;
    const glsl::IdentifierExpr* later = color->id > data->id ? color : data;
    const glsl::IdentifierExpr* earlier = later == color ? data : color;
    Diagnostic diagnostic = MakeDiagnostic(
        Severity::kError, std::string(kId), later->range,
        "a fragment shader cannot use both gl_FragColor and gl_FragData; write gl_FragData[0] "
        "instead of gl_FragColor");
    diagnostic.notes.push_back({earlier->range, "'" + earlier->name + "' is used here"});
    context.Report(std::move(diagnostic));
  }
};

}  // namespace

const rule::Rule& WebglFragDataAndColorRule() {
  static const FragDataAndColorRule rule;
  return rule;
}

}  // namespace shaderport::rules
