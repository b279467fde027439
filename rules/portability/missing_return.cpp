// portability/missing-return: a function with a return type whose end can be
// reached, so that it returns no value on some path (an `if` without `else`, a
// `switch` without `default`). Browsers return zero there (measured in Chromium:
// `float f(int i) { if (i == 0) return 0.25; }` gives 0 for i = 1); native GL,
// Vulkan and Metal return an undefined value. As clang's -Wreturn-type, with the
// browser's zero written as the fix:
//
//   float f(int i) { if (i == 0) return 0.25; }
//   float f(int i) { if (i == 0) return 0.25; return 0.0; }
//
// The end is reachable unless every path returns, discards, or stays in a loop
// whose condition is missing or `true` and that no `break` leaves.
#include <string>

#include "diag/statement_insertion.h"
#include "glsl/webgl_semantics/zero_value.h"
#include "rules/all_rules.h"
#include "rules/portability/portability_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "portability/missing-return";
constexpr int kMaxDepth = 1000;

struct Flow {
  bool completes = true;  // control can leave the statement at its end
  bool breaks = false;    // a `break` leaves the innermost enclosing loop or switch
  bool continues = false;
};

// A missing condition (`for (;;)`) or the literal `true`.
bool AlwaysTrue(const glsl::Node* condition) {
  while (condition != nullptr && condition->kind == glsl::NodeKind::kParenExpr) {
    condition = condition->As<glsl::ParenExpr>()->inner;
  }
  if (condition == nullptr || condition->kind == glsl::NodeKind::kEmptyStatement) return true;
  const auto* literal = condition->As<glsl::LiteralExpr>();
  return literal != nullptr && literal->literal_kind == glsl::LiteralKind::kBool &&
         literal->bool_value;
}

Flow Analyze(const glsl::Node* statement, int depth);

// A loop leaves at its end when its condition can be false or a `break` leaves it.
Flow Loop(bool endless, const Flow& body) { return {!endless || body.breaks, false, false}; }

Flow Sequence(const std::vector<glsl::Node*>& statements, int depth) {
  Flow flow;
  for (const glsl::Node* statement : statements) {
    const Flow next = Analyze(statement, depth + 1);
    flow.breaks = flow.breaks || next.breaks;
    flow.continues = flow.continues || next.continues;
    if (!next.completes) {
      flow.completes = false;
      return flow;
    }
  }
  return flow;
}

Flow Analyze(const glsl::Node* statement, int depth) {
  if (statement == nullptr || depth > kMaxDepth) return {};
  switch (statement->kind) {
    case glsl::NodeKind::kCompoundStatement:
      return Sequence(statement->As<glsl::CompoundStatement>()->statements, depth);
    case glsl::NodeKind::kReturnStatement:
    case glsl::NodeKind::kDiscardStatement:
      return {false, false, false};
    case glsl::NodeKind::kBreakStatement:
      return {false, true, false};
    case glsl::NodeKind::kContinueStatement:
      return {false, false, true};
    case glsl::NodeKind::kIfStatement: {
      const auto* branch = statement->As<glsl::IfStatement>();
      const Flow then = Analyze(branch->then_branch, depth + 1);
      const Flow other =
          branch->else_branch != nullptr ? Analyze(branch->else_branch, depth + 1) : Flow{};
      return {then.completes || other.completes, then.breaks || other.breaks,
              then.continues || other.continues};
    }
    case glsl::NodeKind::kWhileStatement: {
      const auto* loop = statement->As<glsl::WhileStatement>();
      return Loop(AlwaysTrue(loop->condition), Analyze(loop->body, depth + 1));
    }
    case glsl::NodeKind::kForStatement: {
      const auto* loop = statement->As<glsl::ForStatement>();
      return Loop(AlwaysTrue(loop->condition), Analyze(loop->body, depth + 1));
    }
    case glsl::NodeKind::kDoWhileStatement: {
      const auto* loop = statement->As<glsl::DoWhileStatement>();
      const Flow body = Analyze(loop->body, depth + 1);
      // The condition is reached only when the body completes or continues.
      const bool tested = body.completes || body.continues;
      return {(tested && !AlwaysTrue(loop->condition)) || body.breaks, false, false};
    }
    case glsl::NodeKind::kSwitchStatement: {
      const auto* choice = statement->As<glsl::SwitchStatement>();
      bool has_default = false;
      for (const glsl::Node* item :
           choice->body != nullptr ? choice->body->statements : std::vector<glsl::Node*>{}) {
        const auto* label = item->As<glsl::CaseLabel>();
        has_default = has_default || (label != nullptr && label->value == nullptr);
      }
      const Flow body = Analyze(choice->body, depth + 1);
      return {!has_default || body.completes || body.breaks, false, body.continues};
    }
    default:
      return {};
  }
}

// A body closed by its own '}': one the parser ended at the end of the file (a '}'
// missing) ends with the last token of its last statement, and a return put before
// that token would land inside the statement, round after round.
bool ClosedBody(const glsl::CompoundStatement& body, const std::vector<glsl::PpToken>& tokens) {
  if (tokens[body.last_token].text != "}") return false;
  const glsl::Node* last = body.statements.empty() ? nullptr : body.statements.back();
  return last == nullptr || !last->HasTokens() || last->last_token < body.last_token;
}

class MissingReturnRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "Return the browser's zero where a function can end without a return",
        "float f(int i) {\n  if (i == 0) return 0.25;\n}",
        "float f(int i) {\n  if (i == 0) return 0.25;\n return 0.0; }", rule::RuleScope::kLint};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const glsl::TranslationUnit* root = context.Tree().Root();
    if (root == nullptr) return;
    const glsl::SemanticModel& model = context.Model();
    const auto& tokens = context.Preprocessed().tokens;
    for (const glsl::Node* node : root->declarations) {
      const auto* function = node != nullptr ? node->As<glsl::FunctionDeclaration>() : nullptr;
      if (function == nullptr || function->body == nullptr || !function->body->HasTokens() ||
          function->body->last_token >= tokens.size()) {
        continue;
      }
      const uint32_t symbol = model.SymbolAt(function->id);
      if (symbol >= model.symbols.size()) continue;
      const glsl::Type& type = model.symbols[symbol].type;
      if (type.IsVoid() || type.IsUnknown() || !ClosedBody(*function->body, tokens) ||
          !Analyze(function->body, 0).completes) {
        continue;
      }
      const glsl::PpToken& brace = tokens[function->body->last_token];
      Diagnostic diagnostic =
          MakeDiagnostic(Severity::kWarning, std::string(kId), brace.expansion,
                         "'" + function->name.text +
                             "' can reach its end without returning a value: browsers "
                             "return 0, native GL, Vulkan and Metal return an undefined value");
      diagnostic.notes.push_back({function->name.range, "declared to return " + model.Spell(type)});
      const auto zero = glsl::ZeroValue(type, model.structs, model.version);
      if (zero && brace.text == "}" && brace.macro_use == glsl::kNoMacroUse &&
          portability::InThisFile(context, brace.spelling)) {
        diagnostic.fixes.push_back(
            InsertLastStatement(context.File(), brace.spelling.begin, "return " + *zero + ";"));
      }
      context.Report(std::move(diagnostic));
    }
  }
};

}  // namespace

const rule::Rule& PortabilityMissingReturnRule() {
  static const MissingReturnRule rule;
  return rule;
}

}  // namespace shaderport::rules
