// webgl/call-depth: a chain of more than 256 nested calls. Browsers reject the shader
// ("Call stack too deep (larger than 256)"), counting every function with a body,
// called from main or not: a function that calls nothing is 1 deep, its caller 2, and
// the first function deeper than 256 is named. glslang has no such limit.
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "rules/all_rules.h"
#include "rules/webgl/call_graph.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/call-depth";
constexpr uint32_t kMaxDepth = 256;

// Depth of every function of `graph`, iteratively (recursive calls, which
// webgl/recursion reports, count as leaves).
std::map<uint32_t, uint32_t> Depths(const webgl::CallGraph& graph) {
  std::map<uint32_t, uint32_t> depth;  // 0: on the stack
  for (const auto& [root, unused] : graph) {
    if (depth.contains(root)) continue;
    std::vector<std::pair<uint32_t, size_t>> stack = {{root, 0}};
    depth[root] = 0;
    while (!stack.empty()) {
      auto& [function, next] = stack.back();
      const auto found = graph.find(function);
      if (found != graph.end() && next < found->second.size()) {
        const uint32_t callee = found->second[next++].callee;
        if (!depth.contains(callee)) {
          depth[callee] = 0;
          stack.push_back({callee, 0});
        }
        continue;
      }
      uint32_t deepest = 0;
      if (found != graph.end()) {
        for (const webgl::Call& call : found->second)
          deepest = std::max(deepest, depth[call.callee]);
      }
      depth[function] = deepest + 1;
      stack.pop_back();
    }
  }
  return depth;
}

class CallDepthRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "More than 256 nested function calls", "", "",
                                     rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const webgl::CallGraph graph = webgl::BuildCallGraph(context);
    const auto& model = context.Model();
    for (const auto& [function, depth] : Depths(graph)) {
      if (depth != kMaxDepth + 1) continue;
      const glsl::Symbol& symbol = model.symbols[function];
      if (symbol.definition == glsl::kNoNode) continue;
      const auto* declaration =
          context.Tree().NodeAt(symbol.definition).As<glsl::FunctionDeclaration>();
      if (declaration == nullptr) continue;
      webgl::ReportError(context, kId, declaration->name.range,
                         "calls nest more than 256 deep through '" + symbol.name +
                             "'; browsers reject the shader (\"Call stack too deep\")");
    }
  }
};

}  // namespace

const rule::Rule& WebglCallDepthRule() {
  static const CallDepthRule rule;
  return rule;
}

}  // namespace shaderport::rules
