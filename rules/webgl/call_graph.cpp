#include "rules/webgl/call_graph.h"

#include "glsl/syntax/visit.h"

namespace shaderport::rules::webgl {

CallGraph BuildCallGraph(const rule::RuleContext& context) {
  CallGraph graph;
  const glsl::SemanticModel& model = context.Model();
  for (const glsl::Node* declaration : context.Tree().Root()->declarations) {
    const auto* function = declaration->As<glsl::FunctionDeclaration>();
    if (function == nullptr || function->body == nullptr) continue;
    const uint32_t caller = model.SymbolAt(function->id);
    if (caller == glsl::kNoSymbol) continue;
    std::vector<Call>& calls = graph[caller];
    glsl::ForEachNodeOf(context.Tree(), *function->body, {glsl::NodeKind::kCallExpr},
                        [&](const glsl::Node& node) {
                          const auto* call = node.As<glsl::CallExpr>();
                          if (call->call_kind != glsl::CallKind::kFunction) return;
                          const uint32_t callee = model.SymbolAt(call->id);
                          if (callee != glsl::kNoSymbol &&
                              model.symbols[callee].kind == glsl::SymbolKind::kFunction) {
                            calls.push_back({callee, call});
                          }
                        });
  }
  return graph;
}

}  // namespace shaderport::rules::webgl
