// Operand checks for typing/float-modulo: which `%` uses are float remainders,
// whether mod() can take the operands, and the conversions of int operands.
#pragma once

#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "glsl/syntax/ast.h"
#include "rule/rule_context.h"

namespace shaderport::rules::typing {

struct FloatOperands {
  bool floating = false;  // a float operand beside a numeric one: the rule applies
  bool fixable = false;   // mod() accepts the operands once int ones become floats
  std::string why_not;    // when not fixable
  std::string lhs_type;   // spelled, for messages
  std::string rhs_type;
  std::string lhs_float;  // non-empty: the int operand becomes this float type
  std::string rhs_float;
};

// `compound` for `a %= b`: `a` itself must be a float, it receives mod()'s result.
FloatOperands ClassifyModOperands(const rule::RuleContext& context, const glsl::Expr& lhs,
                                  const glsl::Expr& rhs, bool compound = false);

// The fix-its converting the int operands named in `operands` (a literal is
// respelled, anything else wrapped), appended to `fixes`.
void AppendOperandFixes(const rule::RuleContext& context, const FloatOperands& operands,
                        const glsl::Expr& lhs, const glsl::Expr& rhs, std::vector<FixIt>& fixes);

// No calls, assignments, or increments anywhere in `e`: evaluating it twice is harmless.
bool IsSideEffectFree(const glsl::Expr& e);

}  // namespace shaderport::rules::typing
