// webgl/reserved-name: names a WebGL compiler reserves for itself. ANGLE rejects
// every declared name (variable, parameter, function, struct, field, block) that
// starts with `webgl_` or `_webgl_` (WebGL 1.0 spec, "Identifier reserved words"),
// and, in both WebGL versions, any name containing `__`: the GLSL ES specs reserve
// them and Chromium raises an error where desktop compilers only warn.
//
//   uniform vec4 webgl_color;     // error: reserved built-in name
//   float foo__bar;               // error: `__` is reserved
#include <string>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/reserved-name";

const char* ReservedReason(std::string_view name) {
  if (name.starts_with("webgl_") || name.starts_with("_webgl_")) {
    return "names starting with 'webgl_' or '_webgl_' are reserved for the WebGL implementation";
  }
  if (name.find("__") != std::string_view::npos) {
    return "names containing two consecutive underscores are reserved (GLSL ES 3.7); browsers "
           "reject them";
  }
  return nullptr;
}

void CheckName(rule::RuleContext& context, const glsl::Name& name) {
  if (name.Empty()) return;
  if (const char* reason = ReservedReason(name.text)) {
    webgl::ReportError(context, kId, name.range, "'" + name.text + "': " + reason);
  }
}

class ReservedNameRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId,
                                     "A declared name that WebGL reserves (webgl_, _webgl_, __)",
                                     "uniform vec4 webgl_color;", "", rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    constexpr glsl::NodeKinds kNamed = {
        glsl::NodeKind::kDeclarator, glsl::NodeKind::kParameterDeclaration,
        glsl::NodeKind::kFunctionDeclaration, glsl::NodeKind::kStructSpecifier,
        glsl::NodeKind::kInterfaceBlock};
    glsl::ForEachNodeOf(context.Tree(), kNamed, [&](const glsl::Node& node) {
      if (const auto* declarator = node.As<glsl::Declarator>())
        CheckName(context, declarator->name);
      if (const auto* parameter = node.As<glsl::ParameterDeclaration>()) {
        CheckName(context, parameter->name);
      }
      if (const auto* function = node.As<glsl::FunctionDeclaration>()) {
        CheckName(context, function->name);
      }
      if (const auto* structure = node.As<glsl::StructSpecifier>()) {
        CheckName(context, structure->name);
      }
      if (const auto* block = node.As<glsl::InterfaceBlock>()) {
        CheckName(context, block->block_name);
        CheckName(context, block->instance_name);
      }
    });
  }
};

}  // namespace

const rule::Rule& WebglReservedNameRule() {
  static const ReservedNameRule rule;
  return rule;
}

}  // namespace shaderport::rules
