// typing/float-modulo: `%` on floats becomes the built-in mod(). GLSL ES only
// defines `%` for integers (ESSL 1.00 reserves it entirely); float `%` compiles
// nowhere, and mod() is what the author reached for. An int operand beside a
// float one becomes a float too, since mod() converts nothing.
//
// Before:                         After:
//   float r = t % 2.0;              float r = mod(t, 2.0);
//   vec2 c = p % 3;                 vec2 c = mod(p, 3.0);
//   a %= b;                         a = mod(a, b);
#include "glsl/sema/operator_typing.h"
#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/typing/float_operands.h"
#include "rules/typing/typing_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "typing/float-modulo";

class FloatModuloRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "Use mod() for the remainder of floats",
                                     "float r = t % 2.0;", "float r = mod(t, 2.0);",
                                     rule::RuleScope::kAlways};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    if (context.Tree().Root() == nullptr) return;
    glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, uint32_t) {
      if (const auto* b = node.As<glsl::BinaryExpr>();
          b != nullptr && b->op == glsl::BinaryOp::kMod) {
        CheckBinary(context, *b);
      } else if (const auto* a = node.As<glsl::AssignmentExpr>();
                 a != nullptr && a->op == glsl::AssignOp::kMod) {
        CheckCompound(context, *a);
      }
      return true;
    });
  }

 private:
  static void CheckBinary(rule::RuleContext& context, const glsl::BinaryExpr& b) {
    const typing::FloatOperands operands = typing::ClassifyModOperands(context, *b.lhs, *b.rhs);
    if (!operands.floating) return;
    auto diagnostic =
        typing::MakeDiagnostic(kId, Severity::kError, b.range,
                               "'%' is not defined for " + operands.lhs_type + " and " +
                                   operands.rhs_type + " in GLSL ES; use mod()");
    const SourceRange lhs = typing::WrittenRange(context, *b.lhs);
    const SourceRange rhs = typing::WrittenRange(context, *b.rhs);
    if (operands.fixable && typing::InThisFile(context, lhs) && typing::InThisFile(context, rhs) &&
        lhs.file == rhs.file && lhs.end <= rhs.begin) {
      diagnostic.fixes.push_back({{lhs.file, lhs.begin, lhs.begin}, "mod("});
      diagnostic.fixes.push_back({{lhs.file, lhs.end, rhs.begin}, ", "});
      typing::AppendOperandFixes(context, operands, *b.lhs, *b.rhs, diagnostic.fixes);
      diagnostic.fixes.push_back({{rhs.file, rhs.end, rhs.end}, ")"});
    } else if (!operands.fixable) {
      diagnostic.notes.push_back({{}, "not fixed automatically: " + operands.why_not});
    }
    context.Report(std::move(diagnostic));
  }

  static void CheckCompound(rule::RuleContext& context, const glsl::AssignmentExpr& a) {
    const typing::FloatOperands operands =
        typing::ClassifyModOperands(context, *a.lhs, *a.rhs, true);
    if (!operands.floating) return;
    auto diagnostic = typing::MakeDiagnostic(
        kId, Severity::kError, a.range,
        "'%=' is not defined for " + operands.lhs_type + " in GLSL ES; use mod()");
    const SourceRange lhs = typing::WrittenRange(context, *a.lhs);
    const SourceRange rhs = typing::WrittenRange(context, *a.rhs);
    const bool pure = typing::IsSideEffectFree(*a.lhs);
    if (operands.fixable && pure && typing::InThisFile(context, lhs) &&
        typing::InThisFile(context, rhs) && lhs.file == rhs.file && lhs.end <= a.op_range.begin &&
        a.op_range.end <= rhs.begin && !context.InMacro(lhs)) {
      // `a %= b` -> `a = mod(a, b)`: `a` is evaluated twice, so it must be pure.
      diagnostic.fixes.push_back({a.op_range, "= mod(" + std::string(context.TextOf(lhs)) + ","});
      typing::AppendOperandFixes(context, operands, *a.lhs, *a.rhs, diagnostic.fixes);
      diagnostic.fixes.push_back({{rhs.file, rhs.end, rhs.end}, ")"});
    } else if (!pure) {
      diagnostic.notes.push_back(
          {{},
           "not fixed automatically: the left operand has side effects; write "
           "'x = mod(x, y)' with a temporary"});
    } else if (!operands.fixable) {
      diagnostic.notes.push_back({{}, "not fixed automatically: " + operands.why_not});
    }
    context.Report(std::move(diagnostic));
  }
};

}  // namespace

const rule::Rule& TypingFloatModuloRule() {
  static const FloatModuloRule rule;
  return rule;
}

}  // namespace shaderport::rules
