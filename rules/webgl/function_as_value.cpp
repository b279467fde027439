// webgl/function-as-value: a built-in function's name used as a value (`x = abs;`,
// `abs + 1.0`) where no variable of that name is declared, or called where a global
// variable of that name, declared before, hides the built-in. Browsers reject both
// ("function name expected"); glslang lets them pass.
//
//   float t = floor;           // error: floor(x)
//   uniform int abs;  ... abs(x)   // error: the variable hides abs()
#include <map>
#include <string>
#include <string_view>

#include "glsl/sema/builtins.h"
#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/function-as-value";

class FunctionAsValueRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "A built-in function's name used as a value, or called where a variable hides it",
        "float t = floor;", "", rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    glsl::ForEachNodeOf(
        context.Tree(), {glsl::NodeKind::kIdentifierExpr}, [&](const glsl::Node& node) {
          const auto& identifier = *node.As<glsl::IdentifierExpr>();
          const uint32_t symbol = context.Model().SymbolAt(node.id);
          if ((symbol != glsl::kNoSymbol &&
               context.Model().symbols[symbol].kind != glsl::SymbolKind::kBuiltinFunction) ||
              !glsl::IsBuiltinFunctionName(identifier.name)) {
            return;
          }
          webgl::ReportError(context, kId, node.range,
                             "'" + identifier.name +
                                 "' is a built-in function, not a value; browsers reject it "
                                 "(\"function name expected\")");
        });
    // Calls of a built-in whose name a global variable declared before them hides.
    const glsl::SemanticModel& model = context.Model();
    std::multimap<std::string_view, const glsl::Symbol*> hiding;  // by name, in symbol order
    for (const glsl::Symbol& variable : model.symbols) {
      if (variable.kind == glsl::SymbolKind::kVariable && variable.scope == 0 &&
          !variable.predeclared && variable.declaration != glsl::kNoNode &&
          glsl::IsBuiltinFunctionName(variable.name)) {
        hiding.emplace(variable.name, &variable);
      }
    }
    if (hiding.empty()) return;
    glsl::ForEachNodeOf(context.Tree(), {glsl::NodeKind::kCallExpr}, [&](const glsl::Node& node) {
      const auto& call = *node.As<glsl::CallExpr>();
      if (call.call_kind != glsl::CallKind::kFunction) return;
      const auto [begin, end] = hiding.equal_range(call.callee.text);
      for (auto found = begin; found != end; ++found) {
        const glsl::Symbol& variable = *found->second;
        const SourceRange& declared = context.Tree().NodeAt(variable.declaration).range;
        if (declared.file != call.callee.range.file || declared.begin > call.callee.range.begin) {
          continue;
        }
        webgl::ReportError(context, kId, call.callee.range,
                           "'" + call.callee.text +
                               "' names a global variable here, which hides the built-in "
                               "function; browsers reject the call (\"function name "
                               "expected\")");
        return;
      }
    });
  }
};

}  // namespace

const rule::Rule& WebglFunctionAsValueRule() {
  static const FunctionAsValueRule rule;
  return rule;
}

}  // namespace shaderport::rules
