// webgl/recursion: a function that calls itself, directly or through others.
// GLSL ES forbids static recursion (1.00 section 6.1, 3.00 section 6.1); glslang
// only notices it when linking a whole program, browsers reject the shader.
//
//   float a(float x);
//   float b(float x) { return a(x); }
//   float a(float x) { return b(x); }   // error: a -> b -> a
#include <map>
#include <string>
#include <vector>

#include "rules/all_rules.h"
#include "rules/webgl/call_graph.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/recursion";

class RecursionRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "A function calls itself, directly or through others",
                                     "float f(float x) { return f(x); }", "",
                                     rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const webgl::CallGraph graph = webgl::BuildCallGraph(context);
    enum class Color { kWhite, kGray, kBlack };
    std::map<uint32_t, Color> color;
    const auto& symbols = context.Model().symbols;
    for (const auto& [root, unused] : graph) {
      if (color[root] != Color::kWhite) continue;
      // Iterative depth-first search; `path` holds the functions on the stack.
      struct Frame {
        uint32_t function;
        size_t next = 0;
      };
      std::vector<Frame> stack = {{root}};
      std::vector<uint32_t> path = {root};
      color[root] = Color::kGray;
      while (!stack.empty()) {
        Frame& frame = stack.back();
        const auto found = graph.find(frame.function);
        const std::vector<webgl::Call>* calls = found == graph.end() ? nullptr : &found->second;
        if (calls == nullptr || frame.next >= calls->size()) {
          color[frame.function] = Color::kBlack;
          stack.pop_back();
          path.pop_back();
          continue;
        }
        const webgl::Call call = (*calls)[frame.next++];
        Color& callee_color = color[call.callee];
        if (callee_color == Color::kGray) {
          std::string chain;
          bool in_cycle = false;
          for (uint32_t function : path) {
            in_cycle = in_cycle || function == call.callee;
            if (in_cycle) chain += symbols[function].name + " -> ";
          }
          chain += symbols[call.callee].name;
          webgl::ReportError(context, kId, call.site->callee.range,
                             "recursive call: " + chain +
                                 "; GLSL ES does not allow recursion, browsers reject it");
        } else if (callee_color == Color::kWhite) {
          callee_color = Color::kGray;
          stack.push_back({call.callee});
          path.push_back(call.callee);
        }
      }
    }
  }
};

}  // namespace

const rule::Rule& WebglRecursionRule() {
  static const RecursionRule rule;
  return rule;
}

}  // namespace shaderport::rules
