// The range of values an int or float expression can take, as a closed interval
// (a small interval analysis for the portability/* rules): literals and const
// variables, the index of a `for (int i = A; i < B; i++)` loop (<=, >, >=, !=,
// ++i, i += k, decrements) with constant bounds and no write to the index in the
// body, + - * / with known ranges, clamp/min/max/abs/floor/ceil/round/trunc/sign,
// `% N` (-(N-1)..N-1, or 0..N-1 when the left side is known non-negative or of
// unknown sign), `& N`, `>> k`, int() and float(), float mod() by a constant,
// comparisons and logic (0 or 1). A ?: narrows the variables its condition tests in
// each branch; callers may narrow more (the guards of an if) with overrides.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <utility>

#include "glsl/sema/semantic_model.h"
#include "glsl/syntax/ast.h"
#include "rule/rule_context.h"

namespace shaderport::rules::portability {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// A closed interval; an unbounded side is infinite. The default knows nothing.
struct Range {
  double lo = -kInf;
  double hi = kInf;

  bool Finite() const { return std::isfinite(lo) && std::isfinite(hi); }
  bool Single() const { return Finite() && lo == hi; }
  // A condition's value: nonzero for sure, or zero for sure.
  bool SurelyTrue() const { return lo > 0.0 || hi < 0.0; }
  bool SurelyFalse() const { return lo == 0.0 && hi == 0.0; }
};

// Ranges of some variables that hold at one place (narrowed by guards, or known
// from constants assigned just before), by symbol.
using Overrides = std::unordered_map<uint32_t, Range>;

class ValueRanges {
 public:
  // Finds the loops of the whole tree and the ranges of their indices.
  explicit ValueRanges(const rule::RuleContext& context);

  // The range of `expr`, with the overrides in place.
  Range Of(const glsl::Expr* expr, int depth = 0) const;

  void SetOverrides(const Overrides* overrides) { overrides_ = overrides; }

  // Runs `fn` with other overrides in place.
  template <class Fn>
  Range WithOverrides(const Overrides* overrides, const Fn& fn) const {
    const Overrides* saved = std::exchange(overrides_, overrides);
    const Range range = fn();
    overrides_ = saved;
    return range;
  }

  // Narrows `overrides` by `condition` having the value `truth`: `i < 3` true gives
  // i at most 2; && and || of such tests, and !, are followed.
  void Assume(const glsl::Expr* condition, bool truth, Overrides& overrides, int depth = 0) const;

 private:
  bool Integral(const glsl::Expr& expr) const { return model_.TypeOf(expr.id).IsIntegral(); }
  Range ByType(const glsl::Expr& expr) const;
  static Range Literal(const glsl::LiteralExpr& literal);
  Range Identifier(const glsl::Expr& expr, int depth) const;
  Range Unary(const glsl::UnaryExpr& unary, int depth) const;
  Range Binary(const glsl::BinaryExpr& binary, int depth) const;
  Range Call(const glsl::CallExpr& call, int depth) const;
  bool IsIndex(const glsl::Expr* expr, uint32_t symbol) const;
  void AddLoop(const glsl::ForStatement& loop);

  const rule::RuleContext& context_;
  const glsl::SemanticModel& model_;
  std::unordered_map<uint32_t, Range> loop_ranges_;
  mutable const Overrides* overrides_ = nullptr;
};

}  // namespace shaderport::rules::portability
