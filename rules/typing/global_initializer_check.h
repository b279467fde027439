// Expression checks for typing/non-constant-global-initializer: what GLSL ES
// calls a constant expression, and which initializers may run at the start of
// the entry function instead without changing their value.
#pragma once

#include <string>

#include "glsl/syntax/ast.h"
#include "rule/rule_context.h"

namespace shaderport::rules::typing {

enum class Constness {
  kConstant,     // literals, const variables, constructors and built-in calls of them
  kNotConstant,  // reads a variable, calls a user function, samples a texture...
  kUnknown,      // an unresolved name or broken code: better say nothing
};

Constness ClassifyInitializer(const rule::RuleContext& context, const glsl::Expr& e);

// Empty when `e` reads only global-scope variables (uniforms, globals, built-in
// variables) and calls only built-ins and constructors, so evaluating it first
// thing in main() gives the value the browser computed; else the reason why not.
std::string WhyNotMovable(const rule::RuleContext& context, const glsl::Expr& e);

// Whether a strict-typing rule also has something to fix inside `e`.
bool HasTypingFindings(const rule::RuleContext& context, const glsl::Expr& e);

}  // namespace shaderport::rules::typing
