// Shared pieces of the strict-typing rules (rules/typing/*): walking up the
// tree, spelling int literals as floats, and fix-its that wrap an expression in a
// constructor call without touching the code around it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "glsl/sema/semantic_model.h"
#include "glsl/syntax/ast.h"
#include "rule/rule_context.h"

namespace shaderport::rules::typing {

// The parent of every node, by node id (kNoNode for the root).
std::vector<uint32_t> ParentMap(const glsl::SyntaxTree& tree);

// `e` without surrounding parentheses and unary + or -: `-(3)` gives the literal 3.
const glsl::Expr* StripParensAndSign(const glsl::Expr* e);

// The int literal `e` stands for (through parentheses and signs), or nullptr.
const glsl::LiteralExpr* AsIntLiteral(const glsl::Expr* e);

// `1` -> "1.0", `0x10` -> "16.0", `010` -> "8.0"; nothing when the value overflows.
std::optional<std::string> FloatSpelling(const glsl::LiteralExpr& literal);

// Whether the rule may edit the bytes of `range`: written in the file being fixed.
// Macro ranges are the RuleContext's business (it drops such fixes with a note).
bool InThisFile(const rule::RuleContext& context, const SourceRange& range);

// Where the bytes of `node` are written: its range in the file, or, when all of
// it comes from one #define body, its range in that body (an edit there is
// settled by the macro agreement check of RuleContext::Report).
SourceRange WrittenRange(const rule::RuleContext& context, const glsl::Node& node);

// Fix-its turning `e` into `callee(e)`. A parenthesised `e` only gets `callee` in
// front: `(a + b)` -> `float(a + b)`. Two insertions, so that fixes inside `e`
// (an int literal in a vector initializer...) do not overlap them. Empty when
// `e` is not written in this file.
std::vector<FixIt> WrapInCall(const rule::RuleContext& context, const glsl::Expr& e,
                              std::string_view callee);

// "in an initializer", "in an argument", ... for messages.
const char* DescribeContext(glsl::MismatchContext context);

// One place where an int-typed expression is used where a float type is required:
// the semantic model's kIntForFloat mismatches plus the struct and array
// constructor arguments that it does not record.
struct IntForFloatSite {
  const glsl::Expr* expr = nullptr;
  glsl::Type required;
  glsl::Type actual;
  std::string where;             // "in an initializer"
  std::string not_fixable_note;  // non-empty when wrapping would break the code (out argument)
};

std::vector<IntForFloatSite> IntForFloatSites(const rule::RuleContext& context);

// A diagnostic of `rule_id` on `range`.
Diagnostic MakeDiagnostic(std::string_view rule_id, Severity severity, const SourceRange& range,
                          std::string message);

}  // namespace shaderport::rules::typing
