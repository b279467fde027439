// portability/infinite-loop: a loop that, once entered, never ends: no `break`,
// `return` or `discard` leaves it, and its condition is missing or `true`, or reads
// only variables that nothing in the loop changes (clang-tidy's
// bugprone-infinite-loop). On the GPU such a loop hangs the draw until the browser's
// watchdog loses the WebGL context (the ShaderToy page freezes, then goes blank):
//
//   for (;;) { p += d; }                      // no exit
//   float t = 0.0; while (t < 1.0) { p += d; } // t never changes
//
// A loop that calls a function of the shader while its condition reads a global is
// left alone (the function may change it), as is a condition with a call or a write.
#include <set>
#include <string>
#include <vector>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/portability/portability_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "portability/infinite-loop";

bool IsLoop(glsl::NodeKind kind) {
  return kind == glsl::NodeKind::kForStatement || kind == glsl::NodeKind::kWhileStatement ||
         kind == glsl::NodeKind::kDoWhileStatement;
}

// A `return` or `discard` anywhere in `body`, or a `break` that leaves this loop
// (not one inside a nested loop or switch).
bool CanLeave(const glsl::Node& body) {
  bool leaves = false;
  glsl::VisitPreorder(body, [&](const glsl::Node& node, int /*depth*/) {
    if (leaves) return false;
    switch (node.kind) {
      case glsl::NodeKind::kReturnStatement:
      case glsl::NodeKind::kDiscardStatement:
        leaves = true;
        return false;
      default:
        break;
    }
    return true;
  });
  if (leaves) return true;
  glsl::VisitPreorder(body, [&](const glsl::Node& node, int /*depth*/) {
    if (leaves) return false;
    if (IsLoop(node.kind) || node.kind == glsl::NodeKind::kSwitchStatement) return false;
    if (node.kind == glsl::NodeKind::kBreakStatement) leaves = true;
    return !leaves;
  });
  return leaves;
}

// A call that may change a global: one of the shader's own functions, or a call
// the model could not resolve. Constructors, methods and built-ins change nothing.
bool MayChangeGlobals(const glsl::SemanticModel& model, const glsl::Node& node) {
  const auto* call = node.As<glsl::CallExpr>();
  if (call == nullptr || call->call_kind != glsl::CallKind::kFunction) return false;
  const uint32_t callee = model.SymbolAt(node.id);
  return callee == glsl::kNoSymbol || model.symbols[callee].kind == glsl::SymbolKind::kFunction;
}

struct Condition {
  bool always_true = false;
  bool analysable = true;                // no call of the shader's functions, no write
  std::set<uint32_t> variables;          // the symbols it reads
  std::vector<std::string> names;        // those that could change (not constants), in order
  std::vector<std::string> fixed_names;  // constants, uniforms and built-in inputs
  bool reads_global = false;
};

Condition ReadCondition(const rule::RuleContext& context, const glsl::Node* condition) {
  Condition result;
  // `for (;;)`: no condition node, or an empty one.
  if (condition == nullptr || condition->kind == glsl::NodeKind::kEmptyStatement) {
    result.always_true = true;
    return result;
  }
  const glsl::Expr* expr =
      condition->IsExpr() ? portability::Unparenthesized(static_cast<const glsl::Expr*>(condition))
                          : nullptr;
  if (expr == nullptr) {  // `while (bool b = ...)`: a declaration, written each time
    result.analysable = false;
    return result;
  }
  if (const auto* literal = expr->As<glsl::LiteralExpr>()) {
    result.always_true = literal->literal_kind == glsl::LiteralKind::kBool && literal->bool_value;
    result.analysable = false;
    return result;
  }
  const glsl::SemanticModel& model = context.Model();
  glsl::VisitPreorder(*expr, [&](const glsl::Node& node, int /*depth*/) {
    switch (node.kind) {
      case glsl::NodeKind::kAssignmentExpr:
      case glsl::NodeKind::kErrorExpr:
        result.analysable = false;
        break;
      case glsl::NodeKind::kUnaryExpr: {
        const auto op = node.As<glsl::UnaryExpr>()->op;
        if (op == glsl::UnaryOp::kPreIncrement || op == glsl::UnaryOp::kPreDecrement ||
            op == glsl::UnaryOp::kPostIncrement || op == glsl::UnaryOp::kPostDecrement) {
          result.analysable = false;
        }
        break;
      }
      case glsl::NodeKind::kCallExpr:
        if (MayChangeGlobals(model, node)) result.analysable = false;
        break;
      case glsl::NodeKind::kIdentifierExpr: {
        const uint32_t symbol = model.SymbolAt(node.id);
        if (symbol == glsl::kNoSymbol) {
          result.analysable = false;
          break;
        }
        const glsl::Symbol& s = model.symbols[symbol];
        if (s.kind != glsl::SymbolKind::kVariable && s.kind != glsl::SymbolKind::kParameter &&
            s.kind != glsl::SymbolKind::kBuiltinVariable) {
          break;
        }
        // A constant, a uniform or a built-in input cannot change during the loop.
        const bool fixed =
            s.is_const || s.predeclared || s.kind == glsl::SymbolKind::kBuiltinVariable;
        if (result.variables.insert(symbol).second) {
          (fixed ? result.fixed_names : result.names).push_back(s.name);
        }
        if (!fixed && s.kind != glsl::SymbolKind::kParameter && s.scope == 0) {
          result.reads_global = true;
        }
        break;
      }
      default:
        break;
    }
    return result.analysable;
  });
  return result;
}

// True when nothing in `nodes` writes one of `variables`, and (for a condition that
// reads a global) nothing calls one of the shader's functions.
bool NothingChanges(const rule::RuleContext& context, const std::vector<const glsl::Node*>& nodes,
                    const Condition& condition) {
  const glsl::SemanticModel& model = context.Model();
  bool changes = false;
  for (const glsl::Node* node : nodes) {
    if (node == nullptr) continue;
    portability::ForEachWrittenExpr(context, *node, [&](const glsl::Expr& target) {
      // A target that starts from no name (a call's result passed where a call of
      // unknown overload might write) is no variable.
      const glsl::IdentifierExpr* root = portability::ChainRoot(&target);
      if (root == nullptr) return;
      const uint32_t symbol = model.SymbolAt(root->id);
      if (symbol == glsl::kNoSymbol || condition.variables.contains(symbol)) changes = true;
    });
    if (!condition.reads_global) continue;
    glsl::VisitPreorder(*node, [&](const glsl::Node& inner, int /*depth*/) {
      changes = changes || MayChangeGlobals(model, inner);
      return !changes;
    });
  }
  return !changes;
}

std::string NameList(const std::vector<std::string>& names) {
  std::string list;
  for (size_t i = 0; i < names.size(); ++i) {
    if (i > 0) list += i + 1 == names.size() ? " and " : ", ";
    list += "'" + names[i] + "'";
  }
  return list;
}

class InfiniteLoopRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "A loop that never ends once entered",
                                     "for (;;) { p += d; }", "(unchanged)", rule::RuleScope::kLint};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, int /*depth*/) {
      if (IsLoop(node.kind)) Check(context, node);
      return true;
    });
  }

 private:
  static void Check(rule::RuleContext& context, const glsl::Node& loop) {
    const glsl::Node* condition = nullptr;
    const glsl::Node* body = nullptr;
    const glsl::Node* increment = nullptr;
    if (const auto* for_loop = loop.As<glsl::ForStatement>()) {
      condition = for_loop->condition;
      body = for_loop->body;
      increment = for_loop->increment;
    } else if (const auto* while_loop = loop.As<glsl::WhileStatement>()) {
      condition = while_loop->condition;
      body = while_loop->body;
      if (condition == nullptr) return;  // broken code
    } else if (const auto* do_loop = loop.As<glsl::DoWhileStatement>()) {
      condition = do_loop->condition;
      body = do_loop->body;
      if (condition == nullptr) return;
    }
    if (body == nullptr || CanLeave(*body)) return;
    const Condition read = ReadCondition(context, condition);
    std::string why;
    if (read.always_true) {
      why = condition == nullptr || condition->kind == glsl::NodeKind::kEmptyStatement
                ? "it has no condition"
                : "its condition is always true";
    } else if (read.analysable && !read.variables.empty() &&
               NothingChanges(context, {body, increment}, read)) {
      why = read.names.empty()
                ? "its condition reads only " + NameList(read.fixed_names) +
                      ", which cannot change while it runs"
                : "nothing in it changes " + NameList(read.names) + ", which its condition reads";
    } else {
      return;
    }
    const auto& tokens = context.Preprocessed().tokens;
    const SourceRange where = loop.HasTokens() && loop.first_token < tokens.size()
                                  ? tokens[loop.first_token].expansion
                                  : loop.range;
    context.Report(MakeDiagnostic(
        Severity::kWarning, std::string(kId), where,
        "this loop never ends once entered: " + why +
            ", and no break, return or discard leaves it; the GPU hangs until the browser "
            "loses the WebGL context"));
  }
};

}  // namespace

const rule::Rule& PortabilityInfiniteLoopRule() {
  static const InfiniteLoopRule rule;
  return rule;
}

}  // namespace shaderport::rules
