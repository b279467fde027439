#include "glsl/webgl_semantics/driver_folding.h"

#include <algorithm>
#include <array>
#include <string_view>

#include "glsl/webgl_semantics/semantics_context.h"

namespace shaderport::glsl {
namespace {

// The GLSL.std.450 instructions that spirv-opt's constant folding evaluates (its
// const_folding_rules), the optimiser SwiftShader runs on what ANGLE emits; every other
// built-in (radians, abs, floor, fract, mod, length, normalize, smoothstep, ...) is
// computed at run time unless ANGLE folded the whole call (measured in Chromium 156).
bool OptimiserFoldsBuiltin(std::string_view name) {
  static constexpr std::array<std::string_view, 17> kFolded = {
      "min",  "max", "clamp", "mix",  "sin",  "cos",  "tan", "asin", "acos",
      "atan", "exp", "log",   "exp2", "log2", "sqrt", "pow", "dot"};
  return std::find(kFolded.begin(), kFolded.end(), name) != kFolded.end();
}

bool IsIncrementOrDecrement(UnaryOp op) {
  return op == UnaryOp::kPreIncrement || op == UnaryOp::kPreDecrement ||
         op == UnaryOp::kPostIncrement || op == UnaryOp::kPostDecrement;
}

}  // namespace

DriverFolding::DriverFolding(const SyntaxTree& tree, const SemanticModel& model,
                             const std::vector<uint32_t>& parent)
    : tree_(tree),
      model_(model),
      parent_(parent),
      uses_(model.symbols.size()),
      state_(model.symbols.size(), State::kUnknown) {
  for (uint32_t node = 0; node < model.references.size(); ++node) {
    const uint32_t symbol = model.references[node];
    if (symbol < uses_.size()) uses_[symbol].push_back(node);
  }
}

const Node* DriverFolding::Parent(const Node& node) const {
  const uint32_t p = node.id < parent_.size() ? parent_[node.id] : kNoNode;
  return p == kNoNode ? nullptr : &tree_.NodeAt(p);
}

bool DriverFolding::IsFolded(const Expr* expr) const { return IsFolded(expr, 0); }

// Folded by ANGLE (a constant expression, built-in calls included) or by the optimiser
// after ANGLE: what reaches it through variables and parameters folds only through the
// operators, constructors and built-ins it evaluates.
bool DriverFolding::IsFolded(const Expr* expr, int depth) const {
  return IsConstantTree(
      expr, model_,
      [this](const Expr& identifier, int at) {
        return SymbolIsFolded(model_.SymbolAt(identifier.id), at);
      },
      depth,
      [this](const CallExpr& call) {
        return OptimiserFoldsBuiltin(call.callee.text) || IsConstantExpression(&call, model_);
      });
}

bool DriverFolding::SymbolIsFolded(uint32_t symbol_id, int depth) const {
  if (symbol_id >= state_.size()) return false;
  const Symbol& symbol = model_.symbols[symbol_id];
  if (symbol.is_const) return true;
  switch (state_[symbol_id]) {
    case State::kFolded:
      return true;
    case State::kNotFolded:
    case State::kVisiting:  // a cycle: not provably constant
      return false;
    case State::kUnknown:
      break;
  }
  state_[symbol_id] = State::kVisiting;
  bool folded = false;
  if (symbol.kind == SymbolKind::kVariable) folded = VariableIsFolded(symbol, symbol_id, depth);
  if (symbol.kind == SymbolKind::kParameter) folded = ParameterIsFolded(symbol, symbol_id, depth);
  state_[symbol_id] = folded ? State::kFolded : State::kNotFolded;
  return folded;
}

bool DriverFolding::VariableIsFolded(const Symbol& symbol, uint32_t symbol_id, int depth) const {
  if (symbol.declaration == kNoNode || symbol.type.IsArray() || symbol.type.IsStruct()) {
    return false;
  }
  const auto* declarator = tree_.NodeAt(symbol.declaration).As<Declarator>();
  if (declarator == nullptr || declarator->initializer == nullptr) return false;
  for (const uint32_t use : uses_[symbol_id]) {
    if (IsWritten(use)) return false;
  }
  return IsFolded(declarator->initializer, depth + 1);
}

bool DriverFolding::ParameterIsFolded(const Symbol& symbol, uint32_t symbol_id, int depth) const {
  if (symbol.declaration == kNoNode || symbol.type.IsArray() || symbol.type.IsStruct()) {
    return false;
  }
  const Node& declaration = tree_.NodeAt(symbol.declaration);
  const auto* parameter = declaration.As<ParameterDeclaration>();
  const Node* function_node = Parent(declaration);
  const auto* function = function_node ? function_node->As<FunctionDeclaration>() : nullptr;
  if (parameter == nullptr || function == nullptr ||
      parameter->qualifiers.Has(QualifierKind::kOut) ||
      parameter->qualifiers.Has(QualifierKind::kInOut)) {
    return false;
  }
  for (const uint32_t use : uses_[symbol_id]) {
    if (IsWritten(use)) return false;
  }
  size_t position = 0;
  while (position < function->parameters.size() && function->parameters[position] != parameter) {
    ++position;
  }
  const uint32_t function_symbol = model_.SymbolAt(function->id);
  if (function_symbol >= uses_.size()) return false;
  bool called = false;
  for (const uint32_t use : uses_[function_symbol]) {
    const auto* call = tree_.NodeAt(use).As<CallExpr>();
    if (call == nullptr) continue;  // a prototype
    if (position >= call->arguments.size() || !IsFolded(call->arguments[position], depth + 1)) {
      return false;
    }
    called = true;
  }
  return called;
}

// True unless `argument` goes to an `in` parameter of the user function called.
bool DriverFolding::PassedForWriting(const CallExpr& call, const Node& argument) const {
  const uint32_t callee = model_.SymbolAt(call.id);
  if (callee >= model_.symbols.size() || model_.symbols[callee].declaration == kNoNode) return true;
  const auto* function = tree_.NodeAt(model_.symbols[callee].declaration).As<FunctionDeclaration>();
  if (function == nullptr) return true;
  for (size_t i = 0; i < call.arguments.size() && i < function->parameters.size(); ++i) {
    if (call.arguments[i] != &argument) continue;
    const QualifierList& qualifiers = function->parameters[i]->qualifiers;
    return qualifiers.Has(QualifierKind::kOut) || qualifiers.Has(QualifierKind::kInOut);
  }
  return true;
}

// Assigned, incremented, or handed to a function that may write it.
bool DriverFolding::IsWritten(uint32_t use) const {
  const Node* at = &tree_.NodeAt(use);
  for (const Node* up = Parent(*at); up != nullptr; at = up, up = Parent(*up)) {
    if (const auto* member = up->As<MemberExpr>(); member != nullptr && member->object == at) {
      continue;
    }
    if (const auto* index = up->As<IndexExpr>(); index != nullptr && index->base == at) continue;
    if (up->kind == NodeKind::kParenExpr) continue;
    if (const auto* assignment = up->As<AssignmentExpr>()) return assignment->lhs == at;
    if (const auto* unary = up->As<UnaryExpr>()) return IsIncrementOrDecrement(unary->op);
    if (const auto* call = up->As<CallExpr>()) {
      if (call->call_kind != CallKind::kFunction) return false;
      if (model_.builtin_calls.contains(call->id)) {
        return call->callee.text == "modf" || call->callee.text == "frexp";
      }
      return PassedForWriting(*call, *at);
    }
    return false;
  }
  return false;
}

}  // namespace shaderport::glsl
