// webgl/infinite-loop: a loop browsers reject as infinite. ANGLE, compiling for WebGL,
// rejects a `for` or `while` loop (not `do ... while`) whose condition is missing,
// constant and true, or a variable initialised to true that nothing else reads or
// writes, when no `break` of its own and no `return` leaves it ("Infinite loop detected
// in the shader", Chromium 156; ANGLE's PruneInfiniteLoops). `discard` does not count as
// a way out, and the loop is rejected even in a function nothing calls. glslang accepts
// such loops; portability/infinite-loop is the broader lint for loops that never end.
//
//   for (;;) { if (u > 0.5) discard; }   // error: no break or return
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/constant_expression.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/infinite-loop";

// A `break` of this loop (not of a nested loop or switch), or a `return` anywhere in it.
bool HasWayOut(const glsl::Node& body) {
  bool way_out = false;
  glsl::VisitPreorder(body, [&](const glsl::Node& node, int /*depth*/) {
    if (way_out) return false;
    way_out = node.kind == glsl::NodeKind::kReturnStatement;
    return !way_out;
  });
  if (way_out) return true;
  glsl::VisitPreorder(body, [&](const glsl::Node& node, int /*depth*/) {
    if (way_out) return false;
    if (node.kind == glsl::NodeKind::kForStatement ||
        node.kind == glsl::NodeKind::kWhileStatement ||
        node.kind == glsl::NodeKind::kDoWhileStatement ||
        node.kind == glsl::NodeKind::kSwitchStatement) {
      return false;
    }
    way_out = node.kind == glsl::NodeKind::kBreakStatement;
    return !way_out;
  });
  return way_out;
}

class InfiniteLoopRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "A loop browsers reject as infinite",
                                     "for (;;) { if (u > 0.5) discard; }", "",
                                     rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    struct Loop {
      const glsl::Node* node;
      const glsl::Node* condition;
      const glsl::Node* body;
    };
    std::vector<Loop> loops;
    std::vector<const glsl::Node*> bare_conditions;  // identifiers that are a whole condition
    glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, uint32_t /*depth*/) {
      if (const auto* for_loop = node.As<glsl::ForStatement>()) {
        loops.push_back({&node, for_loop->condition, for_loop->body});
      } else if (const auto* while_loop = node.As<glsl::WhileStatement>()) {
        loops.push_back({&node, while_loop->condition, while_loop->body});
      } else {
        return true;
      }
      const glsl::Node* condition = loops.back().condition;
      if (condition != nullptr && condition->IsExpr()) {
        const glsl::Expr* bare = webgl::Unparenthesized(static_cast<const glsl::Expr*>(condition));
        if (bare != nullptr && bare->kind == glsl::NodeKind::kIdentifierExpr) {
          bare_conditions.push_back(bare);
        }
      }
      return true;
    });
    for (const Loop& loop : loops) {
      if (loop.body == nullptr || !AlwaysTrue(context, loop.condition, bare_conditions) ||
          HasWayOut(*loop.body)) {
        continue;
      }
      webgl::ReportError(context, kId, loop.node->range,
                         "browsers reject this loop as infinite ('Infinite loop detected in the "
                         "shader'): its condition never changes and no 'break' or 'return' "
                         "leaves it ('discard' does not count)");
    }
  }

 private:
  static bool AlwaysTrue(const rule::RuleContext& context, const glsl::Node* condition,
                         const std::vector<const glsl::Node*>& bare_conditions) {
    if (condition == nullptr || condition->kind == glsl::NodeKind::kEmptyStatement) return true;
    if (!condition->IsExpr()) return false;
    const auto* expr = static_cast<const glsl::Expr*>(condition);
    if (webgl::ConstantBool(context.Tree(), context.Model(), *expr) == true) return true;
    // A variable initialised to true that nothing reads or writes but loop conditions.
    const glsl::Expr* bare = webgl::Unparenthesized(expr);
    if (bare == nullptr || bare->kind != glsl::NodeKind::kIdentifierExpr) return false;
    const glsl::Declarator* declarator =
        webgl::InitializedDeclarator(context.Tree(), context.Model(), *bare);
    if (declarator == nullptr ||
        webgl::ConstantBool(context.Tree(), context.Model(), *declarator->initializer) != true) {
      return false;
    }
    const uint32_t symbol = context.Model().SymbolAt(bare->id);
    bool other_use = false;
    glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, uint32_t /*depth*/) {
      if (other_use) return false;
      if (node.kind == glsl::NodeKind::kIdentifierExpr &&
          context.Model().SymbolAt(node.id) == symbol &&
          std::find(bare_conditions.begin(), bare_conditions.end(), &node) ==
              bare_conditions.end()) {
        other_use = true;
      }
      return !other_use;
    });
    return !other_use;
  }
};

}  // namespace

const rule::Rule& WebglInfiniteLoopRule() {
  static const InfiniteLoopRule rule;
  return rule;
}

}  // namespace shaderport::rules
