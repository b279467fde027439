// portability/uninitialized-read: a local variable or an out parameter read before
// it is written on some path through its function. Browsers start such variables
// at zero for WebGL; native GL, Vulkan, Metal and D3D leave them undefined, so
// golfed ShaderToy code (`O += ...` on an unwritten `out vec4 O`) reads garbage
// there. The fix writes the zero the browser would.
//
// Before:                                 After:
//   vec4 col2;                              vec4 col2 = vec4(0.0);
//   col2 += texture(iChannel0, uv);         col2 += texture(iChannel0, uv);
//   void mainImage(out vec4 O, vec2 U) {    void mainImage(out vec4 O, vec2 U) { O = vec4(0.0);
//     O += 0.5;                               O += 0.5;
//
// A definite-assignment analysis per function (as clang's -Wsometimes-uninitialized
// or Java's definite assignment): branches intersect what they write (if/else, ?:,
// the right side of && and ||, switch cases), a loop body may run zero times
// (do-while bodies, endless loops and loops whose first test passes for sure run
// at least once: `for (int i = 0; i < 8; i++)`, `float t = 0.0; while (t < 9.0)`;
// the right side of && or || in such a first test runs when the left side's value
// is known), and break, continue, return and discard end a path. Vectors are
// followed per component (`O.rgb = c; O.a = 1.0;` writes all of O); a write into an
// array element, matrix column or struct field writes the whole variable, so that
// such code is never reported falsely. An inout argument is a read unless the
// called function writes that parameter before reading it on every path. A
// harness entry point (mainImage) that returns with an out parameter entirely
// unwritten is reported too: the site's main() reads it.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "diag/statement_insertion.h"
#include "glsl/syntax/visit.h"
#include "glsl/webgl_semantics/zero_value.h"
#include "rules/all_rules.h"
#include "rules/portability/portability_support.h"
#include "rules/portability/value_range.h"

namespace shaderport::rules {
namespace {

using portability::ArgumentUse;

constexpr std::string_view kId = "portability/uninitialized-read";
constexpr std::string_view kWhatHappens =
    ": browsers start it at 0, native GL, Vulkan and Metal leave it undefined";
// Nesting the analysis follows by recursion; deeper code (only machine-made
// expressions are) is left alone.
constexpr int kMaxDepth = 1000;

// A variable the analysis follows: a local declared without an initializer, or
// an out parameter.
struct Slot {
  uint32_t symbol = glsl::kNoSymbol;
  glsl::Type type;
  uint8_t full = 1;     // the bits of every component (1 for what is followed whole)
  bool vector = false;  // followed per component
  const glsl::Declarator* declarator = nullptr;
  const glsl::ParameterDeclaration* parameter = nullptr;
  bool reported = false;
};

// What is written for sure on every path to a point, per slot.
struct State {
  bool reachable = true;
  std::vector<uint8_t> written;
};

State Join(const State& a, const State& b) {
  if (!a.reachable) return b;
  if (!b.reachable) return a;
  State joined = a;
  for (size_t i = 0; i < joined.written.size() && i < b.written.size(); ++i) {
    joined.written[i] &= b.written[i];
  }
  return joined;
}

// Where break and continue go.
struct JumpTarget {
  bool loop = false;  // false: a switch (continue passes through it)
  std::vector<State> breaks;
  std::vector<State> continues;
};

// The part of a followed variable an expression names.
struct Access {
  int slot = -1;
  uint8_t mask = 0;
};

std::string ComponentLetters(uint8_t mask) {
  std::string letters;
  for (int i = 0; i < 4; ++i) {
    if ((mask & (1u << i)) != 0) letters += "xyzw"[i];
  }
  return letters;
}

bool IsBoolLiteral(const glsl::Node* node, bool value) {
  const auto* expr =
      node != nullptr && node->IsExpr() ? static_cast<const glsl::Expr*>(node) : nullptr;
  const auto* literal =
      expr != nullptr ? portability::Unparenthesized(expr)->As<glsl::LiteralExpr>() : nullptr;
  return literal != nullptr && literal->literal_kind == glsl::LiteralKind::kBool &&
         literal->bool_value == value;
}

// What a function does with an inout parameter, seen from its callers.
struct InOutUse {
  bool read_first = true;       // may read it before writing it
  bool always_written = false;  // written on every path that returns
};

// The inout summaries of the functions analysed so far, by definition node.
struct Summaries {
  std::unordered_map<uint32_t, std::vector<InOutUse>> by_function;
  std::unordered_map<uint32_t, bool> in_progress;  // against (invalid) recursion
};

// Ranges of scalar variables known at one point: from what was assigned just before.
using KnownValues = portability::Overrides;

class FunctionAnalysis {
 public:
  FunctionAnalysis(rule::RuleContext& context, const portability::ValueRanges& ranges,
                   const glsl::FunctionDeclaration& function, Summaries& summaries,
                   bool probe = false)
      : context_(context),
        model_(context.Model()),
        ranges_(ranges),
        function_(function),
        summaries_(summaries),
        probe_(probe) {}

  void Run() {
    if (function_.body == nullptr) return;
    CollectSlots();
    if (slots_.empty()) return;
    state_.written.assign(slots_.size(), 0);
    for (size_t i = 0; i < slots_.size(); ++i) {
      // Locals are unset from their declaration on; before it they are out of scope.
      state_.written[i] = slots_[i].parameter != nullptr ? 0 : slots_[i].full;
    }
    exit_.reachable = false;
    Statement(function_.body, 0);
    if (state_.reachable && function_.body->HasTokens()) {
      const SourceRange& body = function_.body->range;
      Returns({body.file, body.end > body.begin ? body.end - 1 : body.end, body.end});
    }
    exit_ = Join(exit_, state_);
  }

  // After a probe run: how the function uses each parameter (inout ones only matter).
  std::vector<InOutUse> ParameterUses() const {
    std::vector<InOutUse> uses(function_.parameters.size());
    for (size_t p = 0; p < function_.parameters.size(); ++p) {
      const auto found = slot_of_.find(model_.SymbolAt(function_.parameters[p]->id));
      if (found == slot_of_.end() || aborted_) continue;
      const auto i = static_cast<size_t>(found->second);
      uses[p].read_first = slots_[i].reported;
      uses[p].always_written = !exit_.reachable || exit_.written[i] == slots_[i].full;
    }
    return uses;
  }

 private:
  void AddSlot(uint32_t symbol, const glsl::Declarator* declarator,
               const glsl::ParameterDeclaration* parameter) {
    if (symbol == glsl::kNoSymbol || symbol >= model_.symbols.size()) return;
    const glsl::Type& type = model_.symbols[symbol].type;
    if (type.IsUnknown() || type.IsVoid() || type.IsSampler()) return;
    Slot slot;
    slot.symbol = symbol;
    slot.type = type;
    slot.vector = type.IsVector() && type.rows <= 4;
    slot.full = slot.vector ? static_cast<uint8_t>((1u << type.rows) - 1) : 1;
    slot.declarator = declarator;
    slot.parameter = parameter;
    slot_of_.emplace(symbol, static_cast<int>(slots_.size()));
    slots_.push_back(slot);
  }

  void CollectSlots() {
    for (const glsl::ParameterDeclaration* parameter : function_.parameters) {
      if (parameter == nullptr || parameter->name.Empty()) continue;
      const bool inout = parameter->qualifiers.Has(glsl::QualifierKind::kInOut);
      if (!parameter->qualifiers.Has(glsl::QualifierKind::kOut) && !(probe_ && inout)) continue;
      AddSlot(model_.SymbolAt(parameter->id), nullptr, parameter);
    }
    constexpr glsl::NodeKinds kDeclarations = {glsl::NodeKind::kVariableDeclaration};
    glsl::ForEachNodeOf(context_.Tree(), *function_.body, kDeclarations,
                        [&](const glsl::Node& node) {
                          const auto* declaration = node.As<glsl::VariableDeclaration>();
                          if (!declaration->qualifiers.Has(glsl::QualifierKind::kConst)) {
                            for (const glsl::Declarator* declarator : declaration->declarators) {
                              if (declarator == nullptr || declarator->initializer != nullptr ||
                                  declarator->name.Empty()) {
                                continue;
                              }
                              AddSlot(model_.SymbolAt(declarator->id), declarator, nullptr);
                            }
                          }
                          return false;  // a struct defined here has fields, not variables
                        });
  }

  int SlotOf(const glsl::Expr& identifier) const {
    const auto found = slot_of_.find(model_.SymbolAt(identifier.id));
    return found == slot_of_.end() ? -1 : found->second;
  }

  std::optional<int64_t> ConstantInt(const glsl::Expr* expr) const {
    expr = portability::Unparenthesized(expr);
    if (expr == nullptr) return std::nullopt;
    if (const auto* literal = expr->As<glsl::LiteralExpr>()) {
      if ((literal->literal_kind == glsl::LiteralKind::kInt ||
           literal->literal_kind == glsl::LiteralKind::kUint) &&
          !literal->int_overflow) {
        return static_cast<int64_t>(literal->int_value);
      }
      return std::nullopt;
    }
    if (expr->kind == glsl::NodeKind::kIdentifierExpr) {
      const uint32_t symbol = model_.SymbolAt(expr->id);
      if (symbol < model_.symbols.size() && model_.symbols[symbol].is_const) {
        return model_.symbols[symbol].const_value;
      }
    }
    return std::nullopt;
  }

  // ------------------------------------------------------------ the state

  void Read(const Access& access, const glsl::Expr& where) {
    if (!state_.reachable || access.slot < 0) return;
    Slot& slot = slots_[static_cast<size_t>(access.slot)];
    const uint8_t missing =
        static_cast<uint8_t>(access.mask & ~state_.written[static_cast<size_t>(access.slot)]);
    if (missing == 0 || slot.reported) return;
    slot.reported = true;
    if (!probe_) Report(slot, missing, where);
  }

  void Write(const Access& access) {
    if (!state_.reachable || access.slot < 0) return;
    state_.written[static_cast<size_t>(access.slot)] |= access.mask;
  }

  // Walks an access chain (`a[i].xy`) to its root, evaluating the root when it is
  // not a variable and every index on the way, and tells which part of a
  // followed variable the chain names.
  Access Resolve(const glsl::Expr* expr, int depth) {
    std::vector<const glsl::Expr*> chain;  // outermost first
    const glsl::Expr* root = expr;
    while (root != nullptr) {
      if (const auto* paren = root->As<glsl::ParenExpr>()) {
        root = paren->inner;
      } else if (const auto* member = root->As<glsl::MemberExpr>()) {
        chain.push_back(root);
        root = member->object;
      } else if (const auto* index = root->As<glsl::IndexExpr>()) {
        chain.push_back(root);
        root = index->base;
      } else {
        break;
      }
    }
    Access access;
    if (root != nullptr && root->kind == glsl::NodeKind::kIdentifierExpr) {
      access.slot = SlotOf(*root);
    } else {
      Eval(root, depth + 1);
    }
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      if (const auto* index = (*it)->As<glsl::IndexExpr>()) Eval(index->index, depth + 1);
    }
    if (access.slot < 0) return access;
    const Slot& slot = slots_[static_cast<size_t>(access.slot)];
    access.mask = slot.full;
    if (!slot.vector) return access;
    std::vector<int> components;
    for (int i = 0; i < slot.type.rows; ++i) components.push_back(i);
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      std::vector<int> next;
      if (const auto* member = (*it)->As<glsl::MemberExpr>()) {
        const auto swizzle = portability::SwizzleComponents(member->member.text);
        if (!swizzle) return access;
        for (int c : *swizzle) {
          if (c >= static_cast<int>(components.size())) return access;
          next.push_back(components[static_cast<size_t>(c)]);
        }
      } else {
        const auto* index = (*it)->As<glsl::IndexExpr>();
        const auto k = ConstantInt(index->index);
        if (!k || *k < 0 || *k >= static_cast<int64_t>(components.size())) return access;
        next.push_back(components[static_cast<size_t>(*k)]);
      }
      components = std::move(next);
    }
    access.mask = 0;
    for (int c : components) access.mask |= static_cast<uint8_t>(1u << c);
    return access;
  }

  // ---------------------------------------------------------- expressions

  void Eval(const glsl::Expr* expr, int depth) {
    if (expr == nullptr || aborted_) return;
    if (depth > kMaxDepth) {
      aborted_ = true;
      return;
    }
    switch (expr->kind) {
      case glsl::NodeKind::kIdentifierExpr:
      case glsl::NodeKind::kMemberExpr:
      case glsl::NodeKind::kIndexExpr:
      case glsl::NodeKind::kParenExpr:
        Read(Resolve(expr, depth), *expr);
        return;
      case glsl::NodeKind::kUnaryExpr: {
        const auto* unary = static_cast<const glsl::UnaryExpr*>(expr);
        if (unary->op < glsl::UnaryOp::kPreIncrement) {
          Eval(unary->operand, depth + 1);
          return;
        }
        const Access target = Resolve(unary->operand, depth);
        if (unary->operand != nullptr) Read(target, *unary->operand);
        Write(target);
        return;
      }
      case glsl::NodeKind::kBinaryExpr:
        Binary(static_cast<const glsl::BinaryExpr*>(expr), depth);
        return;
      case glsl::NodeKind::kAssignmentExpr: {
        const auto* assignment = static_cast<const glsl::AssignmentExpr*>(expr);
        const Access target = Resolve(assignment->lhs, depth);
        if (assignment->op != glsl::AssignOp::kAssign && assignment->lhs != nullptr) {
          Read(target, *assignment->lhs);
        }
        Eval(assignment->rhs, depth + 1);
        Write(target);
        return;
      }
      case glsl::NodeKind::kConditionalExpr: {
        const auto* conditional = static_cast<const glsl::ConditionalExpr*>(expr);
        Eval(conditional->condition, depth + 1);
        const State before = state_;
        Eval(conditional->if_true, depth + 1);
        const State if_true = state_;
        state_ = before;
        Eval(conditional->if_false, depth + 1);
        state_ = Join(if_true, state_);
        return;
      }
      case glsl::NodeKind::kCallExpr:
        Call(static_cast<const glsl::CallExpr*>(expr), depth);
        return;
      default:
        return;
    }
  }

  // Left-associative chains (`a + b + c + ...`) are walked without recursion.
  void Binary(const glsl::BinaryExpr* expr, int depth) {
    std::vector<const glsl::BinaryExpr*> spine;
    const glsl::Expr* left = expr;
    while (left != nullptr && left->kind == glsl::NodeKind::kBinaryExpr) {
      spine.push_back(static_cast<const glsl::BinaryExpr*>(left));
      left = spine.back()->lhs;
    }
    Eval(left, depth + 1);
    for (auto it = spine.rbegin(); it != spine.rend(); ++it) {
      const glsl::BinaryExpr* binary = *it;
      if (binary->op == glsl::BinaryOp::kLogicalAnd || binary->op == glsl::BinaryOp::kLogicalOr) {
        // The right side may not run: what it writes does not count after, unless
        // the left side's value at a loop's first test makes it run.
        const State before = state_;
        Eval(binary->rhs, depth + 1);
        bool runs = false;
        if (first_test_ != nullptr) {
          const portability::Range lhs = FirstValue(binary->lhs, *first_test_);
          const bool is_and = binary->op == glsl::BinaryOp::kLogicalAnd;
          runs = is_and ? lhs.SurelyTrue() : lhs.SurelyFalse();
        }
        if (!runs) state_ = Join(before, state_);
      } else {
        Eval(binary->rhs, depth + 1);
      }
    }
  }

  void Call(const glsl::CallExpr* call, int depth) {
    if (call->call_kind == glsl::CallKind::kMethod) return;  // `a.length()` reads no value
    if (call->call_kind == glsl::CallKind::kConstructor) {
      for (const glsl::Expr* argument : call->arguments) Eval(argument, depth + 1);
      return;
    }
    // In arguments are evaluated in order; out arguments are written when the call returns.
    std::vector<Access> written;
    const portability::ArgumentUses uses(context_, *call);
    for (size_t i = 0; i < call->arguments.size(); ++i) {
      const glsl::Expr* argument = call->arguments[i];
      ArgumentUse use = uses.Of(i);
      if (use == ArgumentUse::kRead) {
        Eval(argument, depth + 1);
        continue;
      }
      bool writes = true;
      if (use == ArgumentUse::kReadWrite) {
        const InOutUse inout = InOutUseOf(*call, i);
        if (!inout.read_first) use = ArgumentUse::kWrite;
        writes = inout.read_first || inout.always_written;
      }
      const Access target = Resolve(argument, depth);
      if (use == ArgumentUse::kReadWrite && argument != nullptr) Read(target, *argument);
      if (writes) written.push_back(target);
    }
    for (const Access& target : written) Write(target);
  }

  // How the user function `call` resolves to uses its inout parameter `index`,
  // from a probe run of the analysis over its definition.
  InOutUse InOutUseOf(const glsl::CallExpr& call, size_t index) {
    const uint32_t symbol = model_.SymbolAt(call.id);
    if (symbol >= model_.symbols.size()) return {};
    const uint32_t definition = model_.symbols[symbol].definition;
    if (definition == glsl::kNoNode || definition >= context_.Tree().NodeCount()) return {};
    const auto* callee = context_.Tree().NodeAt(definition).As<glsl::FunctionDeclaration>();
    if (callee == nullptr || callee->body == nullptr) return {};
    auto found = summaries_.by_function.find(definition);
    if (found == summaries_.by_function.end()) {
      if (summaries_.in_progress[definition]) return {};
      summaries_.in_progress[definition] = true;
      FunctionAnalysis probe(context_, ranges_, *callee, summaries_, /*probe=*/true);
      probe.Run();
      summaries_.in_progress[definition] = false;
      found = summaries_.by_function.emplace(definition, probe.ParameterUses()).first;
    }
    return index < found->second.size() ? found->second[index] : InOutUse{};
  }

  // The range of `expr` at a loop's first test, with the values in `known`.
  portability::Range FirstValue(const glsl::Expr* expr, const KnownValues& known) const {
    return ranges_.WithOverrides(&known, [&] { return ranges_.Of(expr); });
  }

  // Updates the values known after `statement` ran: constants assigned to scalars
  // are learnt, anything else written is forgotten.
  void Learn(const glsl::Node* statement, KnownValues& known) const {
    if (statement == nullptr) return;
    if (!known.empty()) {  // (nested blocks would walk their statements again and again)
      portability::ForEachWrittenExpr(context_, *statement, [&](const glsl::Expr& target) {
        if (const glsl::IdentifierExpr* root = portability::ChainRoot(&target)) {
          known.erase(model_.SymbolAt(root->id));
        }
      });
    }
    auto learn = [&](uint32_t symbol, const glsl::Expr* value) {
      // Locals only: a call may change a global behind our back.
      if (symbol >= model_.symbols.size() || !model_.symbols[symbol].type.IsScalar() ||
          model_.symbols[symbol].scope == 0 || model_.symbols[symbol].scope == glsl::kNoScope) {
        return;
      }
      const portability::Range range = FirstValue(value, known);
      if (std::isfinite(range.lo) || std::isfinite(range.hi)) known[symbol] = range;
    };
    if (const auto* declaration = statement->As<glsl::VariableDeclaration>()) {
      for (const glsl::Declarator* declarator : declaration->declarators) {
        if (declarator == nullptr || declarator->initializer == nullptr) continue;
        learn(model_.SymbolAt(declarator->id), declarator->initializer);
      }
    } else if (const auto* expression = statement->As<glsl::ExpressionStatement>()) {
      const auto* assignment = expression->expression != nullptr
                                   ? expression->expression->As<glsl::AssignmentExpr>()
                                   : nullptr;
      const glsl::Expr* target =
          assignment != nullptr ? portability::Unparenthesized(assignment->lhs) : nullptr;
      if (assignment != nullptr && assignment->op == glsl::AssignOp::kAssign && target != nullptr &&
          target->kind == glsl::NodeKind::kIdentifierExpr) {
        learn(model_.SymbolAt(target->id), assignment->rhs);
      }
    }
  }

  // ----------------------------------------------------------- statements

  void Declaration(const glsl::VariableDeclaration& declaration, int depth) {
    for (const glsl::Declarator* declarator : declaration.declarators) {
      if (declarator == nullptr) continue;
      if (declarator->initializer != nullptr) {
        Eval(declarator->initializer, depth + 1);
        continue;
      }
      const auto found = slot_of_.find(model_.SymbolAt(declarator->id));
      if (found != slot_of_.end() && state_.reachable) {
        state_.written[static_cast<size_t>(found->second)] = 0;
      }
    }
  }

  // The first test of a for or while loop: an expression or a declaration. True
  // when it passes for sure.
  bool FirstTest(const glsl::Node* condition, const KnownValues& known, int depth) {
    if (condition == nullptr) return true;
    if (!condition->IsExpr()) {
      Statement(condition, depth + 1);
      return false;
    }
    const auto* expr = static_cast<const glsl::Expr*>(condition);
    first_test_ = &known;
    Eval(expr, depth + 1);
    first_test_ = nullptr;
    return FirstValue(expr, known).SurelyTrue();
  }

  void Loop(const glsl::Node* body, const glsl::Expr* increment, bool at_least_once,
            bool condition_can_exit, int depth) {
    const State entry = state_;
    jumps_.push_back({true, {}, {}});
    Statement(body, depth + 1);
    JumpTarget target = std::move(jumps_.back());
    jumps_.pop_back();
    for (const State& jump : target.continues) state_ = Join(state_, jump);
    Eval(increment, depth + 1);
    State exit;
    exit.reachable = false;
    if (condition_can_exit) exit = at_least_once ? state_ : entry;
    for (const State& jump : target.breaks) exit = Join(exit, jump);
    state_ = exit;
  }

  void Switch(const glsl::SwitchStatement& statement, const KnownValues& known, int depth) {
    Eval(statement.selector, depth + 1);
    const State selected = state_;
    state_.reachable = false;  // nothing runs before the first label
    bool has_default = false;
    std::vector<double> labels;
    jumps_.push_back({false, {}, {}});
    if (statement.body != nullptr) {
      for (const glsl::Node* child : statement.body->statements) {
        if (const auto* label = child != nullptr ? child->As<glsl::CaseLabel>() : nullptr) {
          has_default = has_default || label->value == nullptr;
          const portability::Range value = ranges_.Of(label->value);
          if (label->value != nullptr && value.Single()) labels.push_back(value.lo);
          state_ = Join(state_, selected);
          continue;
        }
        Statement(child, depth + 1);
      }
    }
    // Labels for every value the selector can take (`switch (k % 4u)`, cases 0u..3u)
    // are as good as a default.
    const portability::Range values = FirstValue(statement.selector, known);
    if (!has_default && values.Finite() && values.hi - values.lo < 64.0) {
      has_default = true;
      for (double v = std::ceil(values.lo); v <= values.hi; v += 1.0) {
        has_default = has_default && std::find(labels.begin(), labels.end(), v) != labels.end();
      }
    }
    JumpTarget target = std::move(jumps_.back());
    jumps_.pop_back();
    for (const State& jump : target.breaks) state_ = Join(state_, jump);
    if (!has_default) state_ = Join(state_, selected);
    // A continue inside the switch belongs to the enclosing loop.
    for (State& jump : target.continues) {
      for (auto it = jumps_.rbegin(); it != jumps_.rend(); ++it) {
        if (it->loop) {
          it->continues.push_back(std::move(jump));
          break;
        }
      }
    }
  }

  void EndPath() { state_.reachable = false; }

  void Statement(const glsl::Node* node, int depth) {
    // Values known before this statement: only for a statement directly in a block.
    const KnownValues* known = std::exchange(before_, nullptr);
    static const KnownValues kNothingKnown;
    if (known == nullptr) known = &kNothingKnown;
    if (node == nullptr || aborted_) return;
    if (depth > kMaxDepth) {
      aborted_ = true;
      return;
    }
    switch (node->kind) {
      case glsl::NodeKind::kCompoundStatement: {
        KnownValues values;
        for (const glsl::Node* child :
             static_cast<const glsl::CompoundStatement*>(node)->statements) {
          before_ = &values;
          Statement(child, depth + 1);
          Learn(child, values);
        }
        return;
      }
      case glsl::NodeKind::kVariableDeclaration:
        Declaration(*static_cast<const glsl::VariableDeclaration*>(node), depth);
        return;
      case glsl::NodeKind::kExpressionStatement:
        Eval(static_cast<const glsl::ExpressionStatement*>(node)->expression, depth + 1);
        return;
      case glsl::NodeKind::kIfStatement: {
        const auto* statement = static_cast<const glsl::IfStatement*>(node);
        Eval(statement->condition, depth + 1);
        // A condition whose value is known (`#define MODE 1` ... `if (MODE == 1)`)
        // takes one branch only; the other is never run.
        const portability::Range condition = FirstValue(statement->condition, *known);
        const State before = state_;
        if (condition.SurelyFalse()) state_.reachable = false;
        Statement(statement->then_branch, depth + 1);
        const State after_then = state_;
        state_ = before;
        if (condition.SurelyTrue()) state_.reachable = false;
        Statement(statement->else_branch, depth + 1);
        state_ = Join(after_then, state_);
        return;
      }
      case glsl::NodeKind::kForStatement: {
        const auto* loop = static_cast<const glsl::ForStatement*>(node);
        Statement(loop->init, depth + 1);
        KnownValues values = *known;
        Learn(loop->init, values);
        const bool once = FirstTest(loop->condition, values, depth);
        const bool endless = loop->condition == nullptr || IsBoolLiteral(loop->condition, true);
        Loop(loop->body, loop->increment, once, !endless, depth);
        return;
      }
      case glsl::NodeKind::kWhileStatement: {
        const auto* loop = static_cast<const glsl::WhileStatement*>(node);
        const bool once = FirstTest(loop->condition, *known, depth);
        const bool endless = IsBoolLiteral(loop->condition, true);
        Loop(loop->body, nullptr, once, !endless, depth);
        return;
      }
      case glsl::NodeKind::kDoWhileStatement: {
        const auto* loop = static_cast<const glsl::DoWhileStatement*>(node);
        jumps_.push_back({true, {}, {}});
        Statement(loop->body, depth + 1);
        JumpTarget target = std::move(jumps_.back());
        jumps_.pop_back();
        for (const State& jump : target.continues) state_ = Join(state_, jump);
        Eval(loop->condition, depth + 1);
        if (IsBoolLiteral(loop->condition, true)) EndPath();
        for (const State& jump : target.breaks) state_ = Join(state_, jump);
        return;
      }
      case glsl::NodeKind::kSwitchStatement:
        Switch(*static_cast<const glsl::SwitchStatement*>(node), *known, depth);
        return;
      case glsl::NodeKind::kBreakStatement:
        if (!jumps_.empty()) jumps_.back().breaks.push_back(state_);
        EndPath();
        return;
      case glsl::NodeKind::kContinueStatement:
        if (!jumps_.empty()) jumps_.back().continues.push_back(state_);
        EndPath();
        return;
      case glsl::NodeKind::kReturnStatement:
        Eval(static_cast<const glsl::ReturnStatement*>(node)->value, depth + 1);
        Returns(node->range);
        exit_ = Join(exit_, state_);
        EndPath();
        return;
      case glsl::NodeKind::kDiscardStatement:
        EndPath();
        return;
      default:
        return;
    }
  }

  // ------------------------------------------------------------ reporting

  std::optional<std::string> ZeroOf(const Slot& slot) const {
    return glsl::ZeroValue(slot.type, model_.structs, model_.version);
  }

  void FixDeclaration(const Slot& slot, Diagnostic& diagnostic) const {
    const glsl::Declarator& declarator = *slot.declarator;
    if (context_.InMacro(declarator.range)) {
      diagnostic.notes.push_back(
          {declarator.name.range, "not fixed automatically: the declaration comes from a macro"});
      return;
    }
    if (!portability::InThisFile(context_, declarator.range)) return;  // fixed with its file
    const auto zero = ZeroOf(slot);
    if (!zero) {
      diagnostic.notes.push_back(
          {declarator.name.range, "not fixed automatically: " + model_.Spell(slot.type) +
                                      " has no zero value to write in this GLSL ES version"});
      return;
    }
    const SourceRange end{declarator.range.file, declarator.range.end, declarator.range.end};
    diagnostic.fixes.push_back({end, " = " + *zero});
  }

  void FixParameter(const Slot& slot, Diagnostic& diagnostic) const {
    const auto& tokens = context_.Preprocessed().tokens;
    const glsl::CompoundStatement& body = *function_.body;
    const bool brace_ok = body.HasTokens() && body.first_token < tokens.size() &&
                          tokens[body.first_token].macro_use == glsl::kNoMacroUse &&
                          tokens[body.first_token].text == "{" &&
                          portability::InThisFile(context_, tokens[body.first_token].spelling);
    if (!portability::InThisFile(context_, slot.parameter->range)) return;
    if (!brace_ok || context_.InMacro(slot.parameter->range)) {
      diagnostic.notes.push_back(
          {slot.parameter->name.range, "not fixed automatically: the function comes from a macro"});
      return;
    }
    const auto zero = ZeroOf(slot);
    if (!zero) {
      diagnostic.notes.push_back(
          {slot.parameter->name.range, "not fixed automatically: " + model_.Spell(slot.type) +
                                           " has no zero value to write in this GLSL ES version"});
      return;
    }
    const SourceRange brace = tokens[body.first_token].spelling;
    diagnostic.fixes.push_back(InsertFirstStatement(
        context_.File(), brace.end, slot.parameter->name.text + " = " + *zero + ";"));
  }

  // A harness entry point (ShaderToy's mainImage, mainCubemap) returns to code that
  // reads its out parameters: one left entirely unwritten on a path is read
  // undefined there. (Other functions' callers often ignore an out parameter on
  // the paths that skip it, `bool hit(..., out float t)`, so only these count.)
  void Returns(const SourceRange& where) {
    if (probe_ || !state_.reachable) return;
    const std::string& name = function_.name.text;
    if (name != "mainImage" && name != "mainCubemap") return;
    for (size_t i = 0; i < slots_.size(); ++i) {
      Slot& slot = slots_[i];
      if (slot.parameter == nullptr || slot.reported || state_.written[i] != 0) continue;
      slot.reported = true;
      Diagnostic diagnostic =
          MakeDiagnostic(Severity::kWarning, std::string(kId), where,
                         "'" + model_.symbols[slot.symbol].name +
                             "' (an out parameter) may be left unwritten "
                             "when " +
                             name +
                             " returns here, and its caller reads it: browsers return 0, "
                             "native GL, Vulkan and Metal leave it undefined");
      diagnostic.notes.push_back({slot.parameter->name.range,
                                  "an out parameter is not copied in: it starts undefined in "
                                  "the function (GLSL ES section 6.1.1)"});
      FixParameter(slot, diagnostic);
      context_.Report(std::move(diagnostic));
    }
  }

  void Report(const Slot& slot, uint8_t missing, const glsl::Expr& where) {
    const std::string& name = model_.symbols[slot.symbol].name;
    std::string what = "'" + name;
    if (slot.vector && missing != slot.full) what += "." + ComponentLetters(missing);
    what += "'";
    if (slot.parameter != nullptr) what += " (an out parameter)";
    Diagnostic diagnostic =
        MakeDiagnostic(Severity::kWarning, std::string(kId), where.range,
                       what + " may be read before it is written" + std::string(kWhatHappens));
    if (slot.parameter != nullptr) {
      diagnostic.notes.push_back({slot.parameter->name.range,
                                  "an out parameter is not copied in: it starts undefined in "
                                  "the function (GLSL ES section 6.1.1)"});
      FixParameter(slot, diagnostic);
    } else {
      diagnostic.notes.push_back({slot.declarator->name.range, "declared without an initializer"});
      FixDeclaration(slot, diagnostic);
    }
    context_.Report(std::move(diagnostic));
  }

  rule::RuleContext& context_;
  const glsl::SemanticModel& model_;
  const portability::ValueRanges& ranges_;
  const glsl::FunctionDeclaration& function_;
  Summaries& summaries_;
  const bool probe_;  // only summarise how the parameters are used, report nothing
  std::vector<Slot> slots_;
  std::unordered_map<uint32_t, int> slot_of_;
  State state_;
  std::vector<JumpTarget> jumps_;
  State exit_;                               // where the function returns
  const KnownValues* before_ = nullptr;      // for the next statement, see Statement()
  const KnownValues* first_test_ = nullptr;  // while evaluating a loop's first test
  bool aborted_ = false;
};

class UninitializedReadRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "Zero-initialise variables read before they are written, as browsers do",
        "void mainImage(out vec4 O, vec2 U) {\n  vec4 c;\n  c += 0.5;\n  O += c;\n}",
        "void mainImage(out vec4 O, vec2 U) { O = vec4(0.0);\n  vec4 c = vec4(0.0);\n  c += "
        "0.5;\n  O += c;\n}",
        rule::RuleScope::kLint};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const glsl::TranslationUnit* root = context.Tree().Root();
    if (root == nullptr) return;
    Summaries summaries;
    const portability::ValueRanges ranges(context);
    for (const glsl::Node* node : root->declarations) {
      const auto* function = node != nullptr ? node->As<glsl::FunctionDeclaration>() : nullptr;
      if (function == nullptr || function->body == nullptr) continue;
      FunctionAnalysis(context, ranges, *function, summaries).Run();
    }
  }
};

}  // namespace

const rule::Rule& PortabilityUninitializedReadRule() {
  static const UninitializedReadRule rule;
  return rule;
}

}  // namespace shaderport::rules
