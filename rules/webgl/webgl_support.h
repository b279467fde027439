// Shared helpers of the webgl/* check rules: which context and language the
// shader is compiled for, and reporting an error the way the browser raises it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "glsl/sema/semantic_model.h"
#include "glsl/syntax/ast.h"
#include "rule/rule_context.h"

namespace shaderport::rules::webgl {

inline bool InWebgl1(const rule::RuleContext& context) {
  return context.Settings().target == model::Target::kWebGL1;
}
inline bool InWebgl2(const rule::RuleContext& context) { return !InWebgl1(context); }
inline bool IsEssl100(const rule::RuleContext& context) {
  return context.Settings().source_version < 300;
}
inline bool IsFragment(const rule::RuleContext& context) {
  return context.Settings().stage == model::Stage::kFragment;
}

// Reports an error of `rule_id` at `range` with an optional note.
void ReportError(rule::RuleContext& context, std::string_view rule_id, const SourceRange& range,
                 std::string message, std::string note = {});

// The user-declared symbol a name refers to, or nullptr.
const glsl::Symbol* SymbolOf(const rule::RuleContext& context, const glsl::Node& node);

// Strips parentheses: `((a))` is `a`.
const glsl::Expr* Unparenthesized(const glsl::Expr* expr);

// The value of `layout(location = N)` among `qualifiers`, when written as an integer.
std::optional<int64_t> LayoutLocation(const glsl::QualifierList& qualifiers);

// True when the type is a struct that has an array among its fields, at any depth.
bool StructContainsArray(const glsl::SemanticModel& model, const glsl::Type& type);

}  // namespace shaderport::rules::webgl
