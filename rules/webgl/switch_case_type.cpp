// webgl/switch-case-type: a case label whose type differs from the switch
// expression's (an `int` label in a `uint` switch, or the reverse). GLSL ES 3.00
// section 6.2 requires the same type and browsers reject the shader; glslang
// converts the label.
//
//   switch (n) { case 1: break; }   // error when n is a uint: write 1u
#include <string>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/switch-case-type";

bool IsIntegerScalar(const glsl::Type& type) {
  return (type.base == glsl::BaseType::kInt || type.base == glsl::BaseType::kUint) &&
         type.rows == 1 && type.columns == 1 && !type.IsArray();
}

class SwitchCaseTypeRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "A case label of another type than the switch expression",
                                     "uint n = 1u;\nswitch (n) { case 1: break; }", "",
                                     rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const glsl::SemanticModel& model = context.Model();
    glsl::ForEachNodeOf(
        context.Tree(), {glsl::NodeKind::kSwitchStatement}, [&](const glsl::Node& node) {
          const auto& statement = *node.As<glsl::SwitchStatement>();
          if (statement.selector == nullptr || statement.body == nullptr) return;
          const glsl::Type selector = model.TypeOf(statement.selector->id);
          if (!IsIntegerScalar(selector)) return;
          // Labels of this switch only: nested switches are visited on their own.
          for (const glsl::Node* item : statement.body->statements) {
            const auto* label = item->As<glsl::CaseLabel>();
            if (label == nullptr || label->value == nullptr) continue;
            const glsl::Type type = model.TypeOf(label->value->id);
            if (!IsIntegerScalar(type) || type.base == selector.base) continue;
            webgl::ReportError(context, kId, label->value->range,
                               std::string("the case label is ") +
                                   (type.base == glsl::BaseType::kUint ? "a uint" : "an int") +
                                   " but the switch expression is " +
                                   (selector.base == glsl::BaseType::kUint ? "a uint" : "an int") +
                                   "; GLSL ES wants the same type");
          }
        });
  }
};

}  // namespace

const rule::Rule& WebglSwitchCaseTypeRule() {
  static const SwitchCaseTypeRule rule;
  return rule;
}

}  // namespace shaderport::rules
