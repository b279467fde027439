// webgl/glslang-only-builtin: a call of a function the shader does not declare and
// that only glslang has as a built-in (GL_INTEL_shader_integer_functions2's
// `average`, GLSL ES 3.10's `imageLoad`, the GLSL ES 1.00 derivatives without their
// extension). glslang compiles the call; browsers reject it ("no matching overloaded
// function found").
//
//   int a = average(1, 3);   // error in browsers: no built-in 'average'
#include <string>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/glslang_only_functions.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/glslang-only-builtin";

class GlslangOnlyBuiltinRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "A call of a built-in function that glslang has and browsers do not",
        "#version 300 es\nint f() { return average(1, 3); }", "", rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const glsl::SemanticModel& model = context.Model();
    const glsl::PreprocessResult* preprocessed = &context.Preprocessed();
    const int version = context.Settings().source_version;
    glsl::ForEachNodeOf(context.Tree(), {glsl::NodeKind::kCallExpr}, [&](const glsl::Node& node) {
      const auto& call = *node.As<glsl::CallExpr>();
      if (call.call_kind != glsl::CallKind::kFunction ||
          !webgl::IsGlslangOnlyFunction(call.callee.text, version, preprocessed)) {
        return;
      }
      const uint32_t symbol = model.SymbolAt(node.id);
      if (symbol != glsl::kNoSymbol && symbol < model.symbols.size() &&
          model.symbols[symbol].declaration != glsl::kNoNode) {
        return;  // the shader's own function of that name
      }
      webgl::ReportError(context, kId, call.callee.range,
                         "'" + call.callee.text +
                             "': no matching overloaded function found; browsers have no "
                             "built-in '" +
                             call.callee.text + "' (glslang has it from " +
                             std::string(webgl::GlslangOnlyFunctionOrigin(call.callee.text)) + ")");
    });
  }
};

}  // namespace

const rule::Rule& WebglGlslangOnlyBuiltinRule() {
  static const GlslangOnlyBuiltinRule rule;
  return rule;
}

}  // namespace shaderport::rules
