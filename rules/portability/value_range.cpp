#include "rules/portability/value_range.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "glsl/syntax/visit.h"
#include "rules/portability/portability_support.h"

namespace shaderport::rules::portability {
namespace {

constexpr int kMaxDepth = 64;

Range Union(const Range& a, const Range& b) { return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)}; }

Range Truncated(const Range& r) { return {std::trunc(r.lo), std::trunc(r.hi)}; }

Range Truth(bool surely_true, bool surely_false) {
  if (surely_true) return {1.0, 1.0};
  if (surely_false) return {0.0, 0.0};
  return {0.0, 1.0};
}

// The value of `a op b`: 1 when it holds for every pair, 0 when for none.
Range Compare(glsl::BinaryOp op, const Range& a, const Range& b) {
  switch (op) {
    case glsl::BinaryOp::kLess:
      return Truth(a.hi < b.lo, a.lo >= b.hi);
    case glsl::BinaryOp::kGreater:
      return Truth(a.lo > b.hi, a.hi <= b.lo);
    case glsl::BinaryOp::kLessEqual:
      return Truth(a.hi <= b.lo, a.lo > b.hi);
    case glsl::BinaryOp::kGreaterEqual:
      return Truth(a.lo >= b.hi, a.hi < b.lo);
    case glsl::BinaryOp::kEqual:
      return Truth(a.Single() && b.Single() && a.lo == b.lo, a.hi < b.lo || b.hi < a.lo);
    case glsl::BinaryOp::kNotEqual:
      return Truth(a.hi < b.lo || b.hi < a.lo, a.Single() && b.Single() && a.lo == b.lo);
    default:
      return {};
  }
}

}  // namespace

ValueRanges::ValueRanges(const rule::RuleContext& context)
    : context_(context), model_(context.Model()) {
  glsl::ForEachNodeOf(context.Tree(), {glsl::NodeKind::kForStatement},
                      [&](const glsl::Node& node) { AddLoop(*node.As<glsl::ForStatement>()); });
}

// The range of `expr`, with `overrides` for the variables a guard narrowed.
Range ValueRanges::Of(const glsl::Expr* expr, int depth) const {
  if (expr == nullptr || depth > kMaxDepth) return {};
  switch (expr->kind) {
    case glsl::NodeKind::kLiteralExpr:
      return Literal(*static_cast<const glsl::LiteralExpr*>(expr));
    case glsl::NodeKind::kParenExpr:
      return Of(static_cast<const glsl::ParenExpr*>(expr)->inner, depth + 1);
    case glsl::NodeKind::kIdentifierExpr:
      return Identifier(*expr, depth);
    case glsl::NodeKind::kUnaryExpr:
      return Unary(*static_cast<const glsl::UnaryExpr*>(expr), depth);
    case glsl::NodeKind::kBinaryExpr:
      return Binary(*static_cast<const glsl::BinaryExpr*>(expr), depth);
    case glsl::NodeKind::kConditionalExpr: {
      // Each branch sees the variables its condition narrows: `i == 6 ? 0 : i + 1`.
      const auto* conditional = static_cast<const glsl::ConditionalExpr*>(expr);
      Overrides if_true = overrides_ != nullptr ? *overrides_ : Overrides{};
      Overrides if_false = if_true;
      Assume(conditional->condition, true, if_true, depth + 1);
      Assume(conditional->condition, false, if_false, depth + 1);
      return Union(WithOverrides(&if_true, [&] { return Of(conditional->if_true, depth + 1); }),
                   WithOverrides(&if_false, [&] { return Of(conditional->if_false, depth + 1); }));
    }
    case glsl::NodeKind::kCallExpr:
      return Call(*static_cast<const glsl::CallExpr*>(expr), depth);
    default:
      return ByType(*expr);
  }
}

// What the type alone tells: a uint is never negative.
Range ValueRanges::ByType(const glsl::Expr& expr) const {
  const glsl::Type& type = model_.TypeOf(expr.id);
  if (type.base == glsl::BaseType::kUint && type.IsScalar()) return {0.0, kInf};
  return {};
}

Range ValueRanges::Literal(const glsl::LiteralExpr& literal) {
  switch (literal.literal_kind) {
    case glsl::LiteralKind::kInt:
    case glsl::LiteralKind::kUint:
      if (literal.int_overflow) return {};
      return {static_cast<double>(literal.int_value), static_cast<double>(literal.int_value)};
    case glsl::LiteralKind::kFloat:
      return {literal.float_value, literal.float_value};
    case glsl::LiteralKind::kBool:
      return {literal.bool_value ? 1.0 : 0.0, literal.bool_value ? 1.0 : 0.0};
  }
  return {};
}

// Narrows `overrides` by `condition` having the value `truth`.
void ValueRanges::Assume(const glsl::Expr* condition, bool truth, Overrides& overrides,
                         int depth) const {
  condition = Unparenthesized(condition);
  if (condition == nullptr || depth > kMaxDepth) return;
  if (const auto* unary = condition->As<glsl::UnaryExpr>()) {
    if (unary->op == glsl::UnaryOp::kNot) Assume(unary->operand, !truth, overrides, depth + 1);
    return;
  }
  const auto* binary = condition->As<glsl::BinaryExpr>();
  if (binary == nullptr) return;
  if ((binary->op == glsl::BinaryOp::kLogicalAnd && truth) ||
      (binary->op == glsl::BinaryOp::kLogicalOr && !truth)) {
    Assume(binary->lhs, truth, overrides, depth + 1);
    Assume(binary->rhs, truth, overrides, depth + 1);
    return;
  }
  glsl::BinaryOp op = binary->op;
  const glsl::Expr* variable = Unparenthesized(binary->lhs);
  const glsl::Expr* bound_expr = binary->rhs;
  if (variable == nullptr || variable->kind != glsl::NodeKind::kIdentifierExpr) {
    variable = Unparenthesized(binary->rhs);
    bound_expr = binary->lhs;
    switch (op) {  // `K < i` is `i > K`
      case glsl::BinaryOp::kLess:
        op = glsl::BinaryOp::kGreater;
        break;
      case glsl::BinaryOp::kGreater:
        op = glsl::BinaryOp::kLess;
        break;
      case glsl::BinaryOp::kLessEqual:
        op = glsl::BinaryOp::kGreaterEqual;
        break;
      case glsl::BinaryOp::kGreaterEqual:
        op = glsl::BinaryOp::kLessEqual;
        break;
      default:
        break;
    }
  }
  if (variable == nullptr || variable->kind != glsl::NodeKind::kIdentifierExpr) return;
  const uint32_t symbol = model_.SymbolAt(variable->id);
  if (symbol == glsl::kNoSymbol) return;
  const Range bound = WithOverrides(nullptr, [&] { return Of(bound_expr); });
  if (!bound.Single()) return;
  if (!truth) {
    switch (op) {
      case glsl::BinaryOp::kLess:
        op = glsl::BinaryOp::kGreaterEqual;
        break;
      case glsl::BinaryOp::kGreater:
        op = glsl::BinaryOp::kLessEqual;
        break;
      case glsl::BinaryOp::kLessEqual:
        op = glsl::BinaryOp::kGreater;
        break;
      case glsl::BinaryOp::kGreaterEqual:
        op = glsl::BinaryOp::kLess;
        break;
      case glsl::BinaryOp::kEqual:
        op = glsl::BinaryOp::kNotEqual;
        break;
      case glsl::BinaryOp::kNotEqual:
        op = glsl::BinaryOp::kEqual;
        break;
      default:
        return;
    }
  }
  const auto found = overrides.find(symbol);
  Range range = found != overrides.end() ? found->second : Of(variable);
  const bool integral = model_.TypeOf(variable->id).IsIntegral();
  const double k = bound.lo;
  const double step = integral ? 1.0 : 0.0;  // a strict bound on an int moves by one
  switch (op) {
    case glsl::BinaryOp::kLess:
      range.hi = std::min(range.hi, k - step);
      break;
    case glsl::BinaryOp::kLessEqual:
      range.hi = std::min(range.hi, k);
      break;
    case glsl::BinaryOp::kGreater:
      range.lo = std::max(range.lo, k + step);
      break;
    case glsl::BinaryOp::kGreaterEqual:
      range.lo = std::max(range.lo, k);
      break;
    case glsl::BinaryOp::kEqual:
      range = {std::max(range.lo, k), std::min(range.hi, k)};
      break;
    case glsl::BinaryOp::kNotEqual:
      if (integral && range.lo == k) range.lo = k + 1;
      if (integral && range.hi == k) range.hi = k - 1;
      break;
    default:
      return;
  }
  overrides[symbol] = range;
}

Range ValueRanges::Identifier(const glsl::Expr& expr, int depth) const {
  const uint32_t symbol = model_.SymbolAt(expr.id);
  if (symbol == glsl::kNoSymbol || symbol >= model_.symbols.size()) return ByType(expr);
  if (overrides_ != nullptr) {
    if (const auto found = overrides_->find(symbol); found != overrides_->end()) {
      return found->second;
    }
  }
  if (const auto found = loop_ranges_.find(symbol); found != loop_ranges_.end()) {
    return found->second;
  }
  const glsl::Symbol& variable = model_.symbols[symbol];
  if (!variable.is_const || variable.kind != glsl::SymbolKind::kVariable) return ByType(expr);
  if (variable.const_value) {
    const auto value = static_cast<double>(*variable.const_value);
    return {value, value};
  }
  if (variable.declaration != glsl::kNoNode && variable.declaration < context_.Tree().NodeCount()) {
    const auto* declarator = context_.Tree().NodeAt(variable.declaration).As<glsl::Declarator>();
    if (declarator != nullptr && declarator->initializer != nullptr) {
      return Of(declarator->initializer, depth + 1);
    }
  }
  return ByType(expr);
}

Range ValueRanges::Unary(const glsl::UnaryExpr& unary, int depth) const {
  const Range r = Of(unary.operand, depth + 1);
  switch (unary.op) {
    case glsl::UnaryOp::kPlus:
    case glsl::UnaryOp::kPostIncrement:  // the value before the change
    case glsl::UnaryOp::kPostDecrement:
      return r;
    case glsl::UnaryOp::kMinus:
      return {-r.hi, -r.lo};
    case glsl::UnaryOp::kPreIncrement:
      return {r.lo + 1.0, r.hi + 1.0};
    case glsl::UnaryOp::kPreDecrement:
      return {r.lo - 1.0, r.hi - 1.0};
    case glsl::UnaryOp::kNot:
      if (r.SurelyTrue()) return {0.0, 0.0};
      if (r.SurelyFalse()) return {1.0, 1.0};
      return {0.0, 1.0};
    case glsl::UnaryOp::kBitNot:
      break;
  }
  return ByType(unary);
}

Range ValueRanges::Binary(const glsl::BinaryExpr& binary, int depth) const {
  const Range a = Of(binary.lhs, depth + 1);
  const Range b = Of(binary.rhs, depth + 1);
  const bool integral = Integral(binary);
  switch (binary.op) {
    case glsl::BinaryOp::kAdd:
      return {a.lo + b.lo, a.hi + b.hi};
    case glsl::BinaryOp::kSub:
      return {a.lo - b.hi, a.hi - b.lo};
    case glsl::BinaryOp::kMul: {
      if (!a.Finite() || !b.Finite()) return ByType(binary);
      const double p[] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
      return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
    }
    case glsl::BinaryOp::kDiv: {
      if (!a.Finite() || !b.Single() || b.lo == 0.0) return ByType(binary);
      Range q{a.lo / b.lo, a.hi / b.lo};
      if (q.lo > q.hi) std::swap(q.lo, q.hi);
      return integral ? Truncated(q) : q;
    }
    case glsl::BinaryOp::kMod: {
      if (!integral || !b.Single() || b.lo <= 0.0) return ByType(binary);
      const double n = b.lo;
      if (a.lo >= 0.0 && a.hi <= n - 1) return a;
      // GLSL ES 3.00 leaves % of negative operands undefined (section 5.9): a left
      // side of unknown sign is taken to be non-negative, which keeps `k % 3` into a
      // vec3 quiet; a left side known to go negative gives -(N-1)..N-1.
      if (!std::isfinite(a.lo)) return {0.0, std::min(a.hi, n - 1)};
      return {a.lo >= 0.0 ? 0.0 : std::max(a.lo, -(n - 1)),
              a.hi < 0.0 ? 0.0 : std::min(a.hi, n - 1)};
    }
    case glsl::BinaryOp::kBitAnd: {
      if (!integral) return ByType(binary);
      Range r = ByType(binary);
      if (b.Single() && b.lo >= 0.0) r = {0.0, b.lo};
      if (a.Single() && a.lo >= 0.0) r = {0.0, std::min(r.hi, a.lo)};
      if (a.lo >= 0.0 && b.lo >= 0.0) r = {0.0, std::min({r.hi, a.hi, b.hi})};
      return r;
    }
    case glsl::BinaryOp::kShr: {
      if (!integral || !b.Single() || b.lo < 0.0 || b.lo > 31.0 || a.lo < 0.0) {
        return ByType(binary);
      }
      const double scale = std::ldexp(1.0, static_cast<int>(b.lo));
      return {std::floor(a.lo / scale), std::floor(a.hi / scale)};
    }
    case glsl::BinaryOp::kComma:
      return b;
    case glsl::BinaryOp::kLess:
    case glsl::BinaryOp::kGreater:
    case glsl::BinaryOp::kLessEqual:
    case glsl::BinaryOp::kGreaterEqual:
    case glsl::BinaryOp::kEqual:
    case glsl::BinaryOp::kNotEqual:
      return Compare(binary.op, a, b);
    case glsl::BinaryOp::kLogicalAnd:
      if (a.SurelyFalse() || b.SurelyFalse()) return {0.0, 0.0};
      if (a.SurelyTrue() && b.SurelyTrue()) return {1.0, 1.0};
      return {0.0, 1.0};
    case glsl::BinaryOp::kLogicalOr:
      if (a.SurelyTrue() || b.SurelyTrue()) return {1.0, 1.0};
      if (a.SurelyFalse() && b.SurelyFalse()) return {0.0, 0.0};
      return {0.0, 1.0};
    default:
      return ByType(binary);
  }
}

Range ValueRanges::Call(const glsl::CallExpr& call, int depth) const {
  if (call.call_kind == glsl::CallKind::kMethod) {  // `a.length()` of a sized array
    const glsl::Type type = call.object != nullptr ? model_.TypeOf(call.object->id) : glsl::Type{};
    if (call.callee.text != "length") return ByType(call);
    if (type.IsArray() && type.array_size > 0)
      return {double(type.array_size), double(type.array_size)};
    if (type.IsVector()) return {double(type.rows), double(type.rows)};
    if (type.IsMatrix()) return {double(type.columns), double(type.columns)};
    return ByType(call);
  }
  if (call.call_kind == glsl::CallKind::kConstructor) {
    const glsl::Type& type = model_.TypeOf(call.id);
    if (call.arguments.size() != 1 || !type.IsScalar()) return ByType(call);
    const Range r = Of(call.arguments[0], depth + 1);
    if (type.base == glsl::BaseType::kFloat) return r;
    if (type.base == glsl::BaseType::kInt) return Truncated(r);
    if (type.base == glsl::BaseType::kUint) return r.lo >= 0.0 ? Truncated(r) : ByType(call);
    return ByType(call);
  }
  if (call.call_kind != glsl::CallKind::kFunction || !model_.builtin_calls.contains(call.id)) {
    return ByType(call);
  }
  std::vector<Range> args;
  for (const glsl::Expr* argument : call.arguments) args.push_back(Of(argument, depth + 1));
  const std::string& name = call.callee.text;
  if (name == "clamp" && args.size() == 3) {
    return {std::min(std::max(args[0].lo, args[1].lo), args[2].lo),
            std::min(std::max(args[0].hi, args[1].hi), args[2].hi)};
  }
  if (name == "min" && args.size() == 2) {
    return {std::min(args[0].lo, args[1].lo), std::min(args[0].hi, args[1].hi)};
  }
  if (name == "max" && args.size() == 2) {
    return {std::max(args[0].lo, args[1].lo), std::max(args[0].hi, args[1].hi)};
  }
  if (name == "abs" && args.size() == 1) {
    const Range& r = args[0];
    if (r.lo >= 0.0) return r;
    if (r.hi <= 0.0) return {-r.hi, -r.lo};
    return {0.0, std::max(-r.lo, r.hi)};
  }
  if (args.size() == 1 && (name == "floor" || name == "ceil" || name == "trunc" ||
                           name == "round" || name == "roundEven")) {
    const Range& r = args[0];
    if (name == "floor") return {std::floor(r.lo), std::floor(r.hi)};
    if (name == "ceil") return {std::ceil(r.lo), std::ceil(r.hi)};
    if (name == "trunc") return Truncated(r);
    return {std::floor(r.lo), std::ceil(r.hi)};
  }
  if (name == "mod" && args.size() == 2 && args[1].Single() && args[1].lo > 0.0) {
    const double n = args[1].lo;
    if (args[0].lo >= 0.0 && args[0].hi < n) return args[0];
    return {0.0, std::nextafter(n, 0.0)};  // [0, n)
  }
  if (name == "sign" && args.size() == 1) return {-1.0, 1.0};
  return ByType(call);
}

bool ValueRanges::IsIndex(const glsl::Expr* expr, uint32_t symbol) const {
  expr = Unparenthesized(expr);
  return expr != nullptr && expr->kind == glsl::NodeKind::kIdentifierExpr &&
         model_.SymbolAt(expr->id) == symbol;
}

// The values the index of `for (T i = A; i op B; step)` takes, when A, B and the
// step are constants and the body leaves the index alone.
void ValueRanges::AddLoop(const glsl::ForStatement& loop) {
  const auto* init = loop.init != nullptr ? loop.init->As<glsl::VariableDeclaration>() : nullptr;
  if (init == nullptr || init->declarators.size() != 1 || loop.body == nullptr) return;
  const glsl::Declarator* declarator = init->declarators[0];
  if (declarator == nullptr || declarator->initializer == nullptr) return;
  const uint32_t index = model_.SymbolAt(declarator->id);
  if (index == glsl::kNoSymbol || index >= model_.symbols.size()) return;
  const glsl::Type& type = model_.symbols[index].type;
  if (!type.IsScalar() || !(type.IsIntegral() || type.IsFloating())) return;
  const Range start = Of(declarator->initializer);
  if (!start.Single()) return;

  const auto* condition =
      loop.condition != nullptr && loop.condition->IsExpr()
          ? Unparenthesized(static_cast<const glsl::Expr*>(loop.condition))->As<glsl::BinaryExpr>()
          : nullptr;
  if (condition == nullptr) return;
  glsl::BinaryOp op = condition->op;
  Range bound;
  if (IsIndex(condition->lhs, index)) {
    bound = Of(condition->rhs);
  } else if (IsIndex(condition->rhs, index)) {
    bound = Of(condition->lhs);
    switch (op) {  // `B > i` is `i < B`
      case glsl::BinaryOp::kLess:
        op = glsl::BinaryOp::kGreater;
        break;
      case glsl::BinaryOp::kGreater:
        op = glsl::BinaryOp::kLess;
        break;
      case glsl::BinaryOp::kLessEqual:
        op = glsl::BinaryOp::kGreaterEqual;
        break;
      case glsl::BinaryOp::kGreaterEqual:
        op = glsl::BinaryOp::kLessEqual;
        break;
      default:
        break;
    }
  } else {
    return;
  }
  if (!bound.Single()) return;

  double step = 0.0;
  const glsl::Expr* increment = Unparenthesized(loop.increment);
  if (increment == nullptr) return;
  if (const auto* unary = increment->As<glsl::UnaryExpr>()) {
    if (!IsIndex(unary->operand, index)) return;
    if (unary->op == glsl::UnaryOp::kPreIncrement || unary->op == glsl::UnaryOp::kPostIncrement) {
      step = 1.0;
    } else if (unary->op == glsl::UnaryOp::kPreDecrement ||
               unary->op == glsl::UnaryOp::kPostDecrement) {
      step = -1.0;
    }
  } else if (const auto* assignment = increment->As<glsl::AssignmentExpr>()) {
    const Range k = Of(assignment->rhs);
    if (!IsIndex(assignment->lhs, index) || !k.Single()) return;
    if (assignment->op == glsl::AssignOp::kAdd) step = k.lo;
    if (assignment->op == glsl::AssignOp::kSub) step = -k.lo;
  }
  if (step == 0.0 || !std::isfinite(step)) return;

  bool written = false;
  ForEachWrittenExpr(context_, *loop.body, [&](const glsl::Expr& target) {
    const glsl::IdentifierExpr* root = ChainRoot(&target);
    written = written || (root != nullptr && model_.SymbolAt(root->id) == index);
  });
  if (written) return;

  const double a = start.lo;
  const double b = bound.lo;
  const double s = std::abs(step);
  double iterations = 0.0;  // how many values the index takes
  if (step > 0.0 && op == glsl::BinaryOp::kLess && a < b) {
    iterations = std::ceil((b - a) / s);
  } else if (step > 0.0 && op == glsl::BinaryOp::kLessEqual && a <= b) {
    iterations = std::floor((b - a) / s) + 1;
  } else if (step < 0.0 && op == glsl::BinaryOp::kGreater && a > b) {
    iterations = std::ceil((a - b) / s);
  } else if (step < 0.0 && op == glsl::BinaryOp::kGreaterEqual && a >= b) {
    iterations = std::floor((a - b) / s) + 1;
  } else if (op == glsl::BinaryOp::kNotEqual && (b - a) / step > 0.0 &&
             std::floor((b - a) / step) == (b - a) / step) {
    iterations = (b - a) / step;
  }
  if (!(iterations >= 1.0) || iterations > 1e9) return;
  const double last = a + (iterations - 1) * step;
  loop_ranges_[index] = {std::min(a, last), std::max(a, last)};
}

}  // namespace shaderport::rules::portability
