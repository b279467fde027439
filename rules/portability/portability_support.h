// Shared pieces of the portability/* rules: how a call uses each argument, the
// variable an access chain such as `a[i].xy` starts from, swizzle letters, and the
// expressions a piece of code writes to.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

#include "glsl/sema/semantic_model.h"
#include "glsl/syntax/ast.h"
#include "rule/rule_context.h"

namespace shaderport::rules::portability {

// `((e))` is `e`.
const glsl::Expr* Unparenthesized(const glsl::Expr* expr);

// How a call passes one argument: by value, as an out or inout parameter, or
// unknown (an unresolved call, whose argument may be written).
enum class ArgumentUse : uint8_t { kRead, kWrite, kReadWrite, kUnknown };

// How `call` passes each argument, from the user function's parameter qualifiers or
// the built-in overload's (modf's second parameter is out). The callee is looked up
// once, on construction: rules ask about every argument of a call in turn.
class ArgumentUses {
 public:
  ArgumentUses(const rule::RuleContext& context, const glsl::CallExpr& call);
  ArgumentUse Of(size_t index) const;

 private:
  enum class Callee : uint8_t {
    kNotAFunction,  // a constructor or method: reads its arguments
    kOverload,      // a resolved built-in overload
    kAnyOverload,   // an unresolved built-in: any overload's qualifiers
    kDeclaration,   // a user function
    kUnknown,       // unresolved: any argument may be written
  };
  const glsl::CallExpr& call_;
  Callee callee_ = Callee::kUnknown;
  const glsl::BuiltinFunction* overload_ = nullptr;
  const glsl::FunctionDeclaration* declaration_ = nullptr;
};

// The identifier an access chain starts from, through parentheses, `.member` and
// `[index]`: `(a[i]).xy` gives `a`. nullptr when the chain starts elsewhere (a call...).
const glsl::IdentifierExpr* ChainRoot(const glsl::Expr* expr);

// The components a swizzle names (`zy` -> {2, 1}); nothing for a name that is not
// a swizzle of xyzw, rgba or stpq.
std::optional<std::vector<int>> SwizzleComponents(std::string_view name);

// Calls `fn` with every expression written under `start`: assignment targets
// (compound ones included), ++/-- operands and out/inout (or unresolved) arguments.
void ForEachWrittenExpr(const rule::RuleContext& context, const glsl::Node& start,
                        const std::function<void(const glsl::Expr& target)>& fn);

// Whether `range` may be edited by a rule: written in the file being checked.
bool InThisFile(const rule::RuleContext& context, const SourceRange& range);

}  // namespace shaderport::rules::portability
