// Constant expressions as GLSL ES defines them (1.00 and 3.00 section 4.3.3 /
// 5.10 of 1.00 Appendix A): what a browser folds at compile time. glslang folds
// fewer built-in calls, so this is also how `check` recognises its false errors.
#pragma once

#include <optional>
#include <set>

#include "glsl/sema/semantic_model.h"
#include "glsl/syntax/ast.h"

namespace shaderport::rules::webgl {

struct ConstantRules {
  int version = 100;
  // Appendix A's constant-index-expressions also allow these loop indices.
  const std::set<uint32_t>* loop_indices = nullptr;
};

// True when `expr` is a constant expression: literals, const variables, and
// operators, constructors, swizzles, indexing and built-in calls (texture lookups
// and derivatives excepted) over them. Bounded by an explicit stack.
bool IsConstantExpression(const glsl::SemanticModel& model, const glsl::Expr& expr,
                          const ConstantRules& rules);

// The value of a bool constant expression as far as it is folded here: literals, `!`,
// `&&`, `||`, comparisons of int and float constants, and const variables of them;
// nullopt for any other (its value is then unknown here, not false).
std::optional<bool> ConstantBool(const glsl::SyntaxTree& tree, const glsl::SemanticModel& model,
                                 const glsl::Expr& expr);

// The declarator of the variable `expr` names, when it is one with an initializer (not a
// parameter, not a built-in); nullptr otherwise.
const glsl::Declarator* InitializedDeclarator(const glsl::SyntaxTree& tree,
                                              const glsl::SemanticModel& model,
                                              const glsl::Expr& expr);

}  // namespace shaderport::rules::webgl
