#include <algorithm>
#include <bit>

#include "glsl/sema/analyzer.h"
#include "glsl/sema/operator_typing.h"
#include "glsl/sema/overload_resolution.h"

namespace shaderport::glsl {
namespace {

// Direct sub-expressions whose types an expression's own type depends on.
void Operands(const Expr& e, std::vector<const Expr*>& out) {
  auto add = [&out](const Expr* child) {
    if (child != nullptr) out.push_back(child);
  };
  switch (e.kind) {
    case NodeKind::kParenExpr:
      return add(e.As<ParenExpr>()->inner);
    case NodeKind::kUnaryExpr:
      return add(e.As<UnaryExpr>()->operand);
    case NodeKind::kBinaryExpr:
      add(e.As<BinaryExpr>()->lhs);
      return add(e.As<BinaryExpr>()->rhs);
    case NodeKind::kAssignmentExpr:
      add(e.As<AssignmentExpr>()->lhs);
      return add(e.As<AssignmentExpr>()->rhs);
    case NodeKind::kConditionalExpr: {
      const auto* c = e.As<ConditionalExpr>();
      add(c->condition);
      add(c->if_true);
      return add(c->if_false);
    }
    case NodeKind::kCallExpr: {
      const auto* c = e.As<CallExpr>();
      add(c->object);
      for (const Expr* arg : c->arguments) add(arg);
      return;
    }
    case NodeKind::kMemberExpr:
      return add(e.As<MemberExpr>()->object);
    case NodeKind::kIndexExpr:
      add(e.As<IndexExpr>()->base);
      return add(e.As<IndexExpr>()->index);
    default:
      return;
  }
}

// Bit masks over `count` items, fewest bits first (count is small).
std::vector<uint32_t> MasksBySize(size_t count) {
  std::vector<uint32_t> masks;
  for (uint32_t m = 1; m < (1u << count); ++m) masks.push_back(m);
  std::stable_sort(masks.begin(), masks.end(),
                   [](uint32_t a, uint32_t b) { return std::popcount(a) < std::popcount(b); });
  return masks;
}

constexpr size_t kMaxPromotedArguments = 6;

}  // namespace

const Type& Analyzer::TypeAt(const Expr* expr) const {
  static const Type kUnknown = Type::Unknown();
  if (expr == nullptr || expr->id >= types_->size()) return kUnknown;
  return (*types_)[expr->id];
}

Type Analyzer::TypeExpression(const Expr* root) {
  if (root == nullptr) return Type::Unknown();
  if (typing_depth_ == typing_scratch_.size()) typing_scratch_.emplace_back();
  TypingScratch& scratch = typing_scratch_[typing_depth_];
  struct DepthGuard {
    size_t& depth;
    explicit DepthGuard(size_t& d) : depth(d) { ++depth; }
    ~DepthGuard() { --depth; }
    DepthGuard(const DepthGuard&) = delete;
    DepthGuard& operator=(const DepthGuard&) = delete;
  } guard(typing_depth_);
  // Post-order with an explicit stack: children are typed before their parent.
  auto& stack = scratch.stack;
  auto& operands = scratch.operands;
  stack.clear();
  stack.push_back({root, false});
  while (!stack.empty()) {
    auto [expr, expanded] = stack.back();
    stack.pop_back();
    // A name or a literal has no operands: typed at once, not pushed back to wait for
    // them (the same order: it would be the next one popped).
    const bool leaf =
        expr->kind == NodeKind::kIdentifierExpr || expr->kind == NodeKind::kLiteralExpr;
    if (!expanded && !leaf) {
      stack.push_back({expr, true});
      operands.clear();
      Operands(*expr, operands);
      for (auto it = operands.rbegin(); it != operands.rend(); ++it) stack.push_back({*it, false});
      continue;
    }
    Type type = ComputeType(*expr);
    if (expr->id < types_->size()) (*types_)[expr->id] = type;
  }
  return TypeAt(root);
}

Type Analyzer::ComputeType(const Expr& expr) {
  switch (expr.kind) {
    case NodeKind::kLiteralExpr:
      switch (expr.As<LiteralExpr>()->literal_kind) {
        case LiteralKind::kInt:
          return Type::Int();
        case LiteralKind::kUint:
          return Type::Uint();
        case LiteralKind::kFloat:
          return Type::Float();
        case LiteralKind::kBool:
          return Type::Bool();
      }
      return Type::Unknown();
    case NodeKind::kIdentifierExpr: {
      const std::string& name = expr.As<IdentifierExpr>()->name;
      if (uint32_t symbol = Lookup(name); symbol != kNoSymbol) {
        Refer(expr.id, symbol);
        const Symbol& s = model_.symbols[symbol];
        return s.kind == SymbolKind::kFunction ? Type::Unknown() : s.type;
      }
      const BuiltinVariable* var = FindBuiltinVariable(name, model_.version, model_.stage);
      if (var == nullptr) {
        // Also type built-ins of the other version or stage (gl_FragColor in a 3.00 shader):
        // porting rules need their types.
        for (const BuiltinVariable& v : AllBuiltinVariables()) {
          if (v.name == name) var = &v;
        }
      }
      if (var == nullptr) return Type::Unknown();
      auto [it, inserted] = builtin_symbols_.try_emplace(name, kNoSymbol);
      if (inserted) {
        it->second = static_cast<uint32_t>(model_.symbols.size());
        model_.symbols.push_back({.kind = SymbolKind::kBuiltinVariable,
                                  .name = name,
                                  .type = var->type,
                                  .scope = 0,
                                  .is_const = var->storage == BuiltinStorage::kConst,
                                  .const_value = var->storage == BuiltinStorage::kConst
                                                     ? std::optional<int64_t>(var->value)
                                                     : std::nullopt,
                                  .builtin_variable = var});
      }
      Refer(expr.id, it->second);
      return var->type;
    }
    case NodeKind::kParenExpr:
      return TypeAt(expr.As<ParenExpr>()->inner);
    case NodeKind::kUnaryExpr: {
      const auto* u = expr.As<UnaryExpr>();
      return UnaryResultType(u->op, TypeAt(u->operand));
    }
    case NodeKind::kBinaryExpr:
      return BinaryType(*expr.As<BinaryExpr>());
    case NodeKind::kAssignmentExpr:
      return AssignmentType(*expr.As<AssignmentExpr>());
    case NodeKind::kConditionalExpr:
      return ConditionalType(*expr.As<ConditionalExpr>());
    case NodeKind::kCallExpr:
      return CallType(*expr.As<CallExpr>());
    case NodeKind::kMemberExpr:
      return MemberType(*expr.As<MemberExpr>());
    case NodeKind::kIndexExpr:
      return IndexResultType(TypeAt(expr.As<IndexExpr>()->base));
    default:
      return Type::Unknown();
  }
}

Type Analyzer::MemberType(const MemberExpr& member) {
  const Type& object = TypeAt(member.object);
  if (object.IsStruct()) {
    return model_.structs.FieldType(object.struct_id, member.member.text).value_or(Type::Unknown());
  }
  return SwizzleType(object, member.member.text);
}

Type Analyzer::BinaryType(const BinaryExpr& binary) {
  const Type& lhs = TypeAt(binary.lhs);
  const Type& rhs = TypeAt(binary.rhs);
  Type result = BinaryResultType(binary.op, lhs, rhs);
  if (!result.IsUnknown() || lhs.IsUnknown() || rhs.IsUnknown()) return result;
  // An int operand beside a float one: type as if it were a float, and record it.
  if (Type promoted = IntToFloat(lhs); !promoted.IsUnknown() && rhs.base == BaseType::kFloat) {
    result = BinaryResultType(binary.op, promoted, rhs);
    if (!result.IsUnknown()) {
      AddMismatch(binary.lhs, MismatchKind::kIntForFloat, MismatchContext::kBinaryOperand, promoted,
                  lhs);
      return result;
    }
  }
  if (Type promoted = IntToFloat(rhs); !promoted.IsUnknown() && lhs.base == BaseType::kFloat) {
    result = BinaryResultType(binary.op, lhs, promoted);
    if (!result.IsUnknown()) {
      AddMismatch(binary.rhs, MismatchKind::kIntForFloat, MismatchContext::kBinaryOperand, promoted,
                  rhs);
    }
  }
  return result;
}

Type Analyzer::AssignmentType(const AssignmentExpr& assignment) {
  const Type& lhs = TypeAt(assignment.lhs);
  const Type& rhs = TypeAt(assignment.rhs);
  BinaryOp op;
  if (!CompoundAssignOperator(assignment.op, op)) {
    CheckRequired(assignment.rhs, lhs, MismatchContext::kAssignment);
    return lhs;
  }
  if (lhs.IsUnknown() || rhs.IsUnknown() || BinaryResultType(op, lhs, rhs) == lhs) return lhs;
  Type promoted = IntToFloat(rhs);
  if (!promoted.IsUnknown() && BinaryResultType(op, lhs, promoted) == lhs) {
    AddMismatch(assignment.rhs, MismatchKind::kIntForFloat, MismatchContext::kAssignment, promoted,
                rhs);
  }
  return lhs;
}

Type Analyzer::ConditionalType(const ConditionalExpr& conditional) {
  const Type& a = TypeAt(conditional.if_true);
  const Type& b = TypeAt(conditional.if_false);
  if (a == b) return a;
  if (a.IsUnknown() || b.IsUnknown()) return Type::Unknown();
  if (IntToFloat(a) == b) {
    AddMismatch(conditional.if_true, MismatchKind::kIntForFloat, MismatchContext::kTernaryBranch, b,
                a);
    return b;
  }
  if (IntToFloat(b) == a) {
    AddMismatch(conditional.if_false, MismatchKind::kIntForFloat, MismatchContext::kTernaryBranch,
                a, b);
    return a;
  }
  return Type::Unknown();
}

Type Analyzer::CallType(const CallExpr& call) {
  switch (call.call_kind) {
    case CallKind::kConstructor: {
      Type type = ResolveTypeSpecifier(call.constructor_type);
      if (type.array_size == Type::kUnsizedArray && !call.arguments.empty()) {
        type = type.ArrayOf(static_cast<int32_t>(call.arguments.size()));
      }
      return type;
    }
    case CallKind::kMethod:
      return call.callee.text == "length" ? Type::Int() : Type::Unknown();
    case CallKind::kFunction: {
      // The argument list is reused between calls (a heap block per call before); taken
      // out while in use, so a nested call would simply start a list of its own.
      std::vector<Type> args = std::move(call_arguments_);
      args.clear();
      for (const Expr* arg : call.arguments) args.push_back(TypeAt(arg));
      Type type = FunctionCallType(call, args);
      call_arguments_ = std::move(args);
      return type;
    }
  }
  return Type::Unknown();
}

Type Analyzer::FunctionCallType(const CallExpr& call, const std::vector<Type>& args) {
  const std::string& name = call.callee.text;
  std::vector<size_t> int_args;
  for (size_t i = 0; i < args.size() && int_args.size() < kMaxPromotedArguments; ++i) {
    if (!IntToFloat(args[i]).IsUnknown()) int_args.push_back(i);
  }
  auto record_promotions = [&](uint32_t mask, const std::vector<Type>& promoted,
                               MismatchContext context) {
    for (size_t bit = 0; bit < int_args.size(); ++bit) {
      if ((mask & (1u << bit)) == 0) continue;
      size_t i = int_args[bit];
      AddMismatch(call.arguments[i], MismatchKind::kIntForFloat, context, promoted[i], args[i]);
    }
  };
  auto promote = [&](uint32_t mask) {
    std::vector<Type> promoted = args;
    for (size_t bit = 0; bit < int_args.size(); ++bit) {
      if ((mask & (1u << bit)) != 0) promoted[int_args[bit]] = IntToFloat(args[int_args[bit]]);
    }
    return promoted;
  };

  if (std::vector<uint32_t> users = LookupFunctions(name); !users.empty()) {
    Refer(call.id, users.front());
    const Symbol* uncertain = nullptr;
    for (uint32_t id : users) {
      ArgumentMatch m = MatchArguments(model_.symbols[id].parameters, args);
      if (m == ArgumentMatch::kExact) {
        Refer(call.id, id);
        return model_.symbols[id].type;
      }
      if (m == ArgumentMatch::kUncertain && uncertain == nullptr) uncertain = &model_.symbols[id];
    }
    if (uncertain != nullptr) return users.size() == 1 ? uncertain->type : Type::Unknown();
    for (uint32_t mask : MasksBySize(int_args.size())) {
      std::vector<Type> promoted = promote(mask);
      for (uint32_t id : users) {
        if (MatchArguments(model_.symbols[id].parameters, promoted) == ArgumentMatch::kExact) {
          Refer(call.id, id);
          record_promotions(mask, promoted, MismatchContext::kCallArgument);
          return model_.symbols[id].type;
        }
      }
    }
    // A user overload of a built-in name (GLSL ES 1.00 allows one, and browsers let
    // GLSL ES 3.00 code declare `texture` and a few more) leaves the built-ins callable.
    if (BuiltinOverloadList(name).empty()) return Type::Unknown();
  } else if (uint32_t symbol = Lookup(name);
             symbol != kNoSymbol && model_.symbols[symbol].kind == SymbolKind::kStruct) {
    Refer(call.id, symbol);  // a struct constructor the parser took for a call
    return model_.symbols[symbol].type;
  }
  // One lookup of the name answers whether it is a built-in and gives its overloads.
  const std::span<const BuiltinFunction* const> overloads = BuiltinOverloadList(name);
  if (overloads.empty()) return Type::Unknown();
  auto [it, inserted] = builtin_function_symbols_.try_emplace(overloads.data(), kNoSymbol);
  if (inserted) {
    it->second = static_cast<uint32_t>(model_.symbols.size());
    model_.symbols.push_back({.kind = SymbolKind::kBuiltinFunction, .name = name, .scope = 0});
  }
  Refer(call.id, it->second);
  BuiltinCallMatch match = ResolveBuiltinCall(overloads, args, model_.version, model_.stage);
  if (match.function == nullptr) {
    for (uint32_t mask : MasksBySize(int_args.size())) {
      std::vector<Type> promoted = promote(mask);
      match = ResolveBuiltinCall(overloads, promoted, model_.version, model_.stage);
      if (match.function != nullptr && !match.uncertain) {
        record_promotions(mask, promoted, MismatchContext::kBuiltinCallArgument);
        break;
      }
      match = {};
    }
  }
  if (match.function == nullptr) return Type::Unknown();
  if (recording_) model_.builtin_calls[call.id] = match.function;
  return match.function->return_type;
}

bool Analyzer::CheckRequired(const Expr* value, const Type& required, MismatchContext context) {
  const Type& actual = TypeAt(value);
  if (value == nullptr || required.IsUnknown() || actual.IsUnknown() || actual == required) {
    return false;
  }
  if (IntToFloat(actual) == required) {
    AddMismatch(value, MismatchKind::kIntForFloat, context, required, actual);
    return true;
  }
  bool scalar_fits = actual.base == required.base ||
                     (actual.base == BaseType::kInt && required.base == BaseType::kFloat);
  if (required.IsVector() && actual.IsScalar() && scalar_fits) {
    AddMismatch(value, MismatchKind::kScalarForVector, context, required, actual);
    return true;
  }
  return false;
}

void Analyzer::AddMismatch(const Expr* node, MismatchKind kind, MismatchContext context,
                           const Type& required, const Type& actual) {
  if (!recording_ || node == nullptr) return;
  model_.mismatches.push_back({node->id, kind, context, required, actual});
}

std::optional<int64_t> Analyzer::ConstantInt(const Expr* expr, int depth) const {
  if (expr == nullptr || depth > 32) return std::nullopt;
  switch (expr->kind) {
    case NodeKind::kLiteralExpr: {
      const auto* lit = expr->As<LiteralExpr>();
      if (lit->literal_kind != LiteralKind::kInt && lit->literal_kind != LiteralKind::kUint) {
        return std::nullopt;
      }
      if (lit->int_overflow) return std::nullopt;
      return static_cast<int64_t>(lit->int_value);
    }
    case NodeKind::kParenExpr:
      return ConstantInt(expr->As<ParenExpr>()->inner, depth + 1);
    case NodeKind::kUnaryExpr: {
      const auto* u = expr->As<UnaryExpr>();
      std::optional<int64_t> v = ConstantInt(u->operand, depth + 1);
      if (!v) return std::nullopt;
      if (u->op == UnaryOp::kMinus) return -*v;
      if (u->op == UnaryOp::kPlus) return v;
      return std::nullopt;
    }
    case NodeKind::kBinaryExpr: {
      const auto* b = expr->As<BinaryExpr>();
      std::optional<int64_t> l = ConstantInt(b->lhs, depth + 1);
      std::optional<int64_t> r = ConstantInt(b->rhs, depth + 1);
      if (!l || !r) return std::nullopt;
      constexpr int64_t kLimit = int64_t{1} << 32;  // keep the arithmetic far from overflow
      if (*l > kLimit || *l < -kLimit || *r > kLimit || *r < -kLimit) return std::nullopt;
      switch (b->op) {
        case BinaryOp::kAdd:
          return *l + *r;
        case BinaryOp::kSub:
          return *l - *r;
        case BinaryOp::kMul:
          return *l * *r;
        case BinaryOp::kDiv:
          return *r == 0 ? std::nullopt : std::optional<int64_t>(*l / *r);
        case BinaryOp::kMod:
          return *r == 0 ? std::nullopt : std::optional<int64_t>(*l % *r);
        default:
          return std::nullopt;
      }
    }
    case NodeKind::kIdentifierExpr: {
      if (!recording_ || expr->id >= model_.references.size()) {
        uint32_t symbol = Lookup(expr->As<IdentifierExpr>()->name);
        return symbol == kNoSymbol ? std::nullopt : model_.symbols[symbol].const_value;
      }
      uint32_t symbol = model_.references[expr->id];
      if (symbol == kNoSymbol) symbol = Lookup(expr->As<IdentifierExpr>()->name);
      return symbol == kNoSymbol ? std::nullopt : model_.symbols[symbol].const_value;
    }
    default:
      return std::nullopt;
  }
}

}  // namespace shaderport::glsl
