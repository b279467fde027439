// typing/int-expression-for-float: a non-literal int expression where a float is
// required is wrapped in `float(...)` (or `vecN(...)` for an ivecN). The int
// arithmetic inside is kept: the fix never changes what the shader computes.
//
// Before:                         After:
//   float x = 1 / 2;                float x = float(1 / 2);
//   float f = float(i) * n;         (unchanged)
//   uv * i                          uv * float(i)
//   vec2 p = ivec2(1, 2);           vec2 p = vec2(ivec2(1, 2));
#include "rules/all_rules.h"
#include "rules/typing/typing_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "typing/int-expression-for-float";

class IntExpressionForFloatRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "Convert int expressions used as floats with an explicit float(...)",
        "float x = 1 / 2;\nfloat y = t * i;", "float x = float(1 / 2);\nfloat y = t * float(i);",
        rule::RuleScope::kAlways};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    for (const typing::IntForFloatSite& site : typing::IntForFloatSites(context)) {
      if (typing::AsIntLiteral(site.expr) != nullptr) continue;  // int-literal-for-float
      const std::string required = context.Model().Spell(site.required);
      auto diagnostic = typing::MakeDiagnostic(
          kId, Severity::kError, site.expr->range,
          "int expression '" + std::string(context.TextOf(site.expr->range)) + "' (" +
              context.Model().Spell(site.actual) + ") used as " + required + " " + site.where +
              "; convert it explicitly");
      if (!site.not_fixable_note.empty()) {
        diagnostic.notes.push_back({{}, site.not_fixable_note});
      } else {
        diagnostic.fixes = typing::WrapInCall(context, *site.expr, required);
        if (diagnostic.fixes.empty()) {
          diagnostic.notes.push_back(
              {{},
               "not fixed automatically: the expression is not written as one piece in this "
               "file (it is part of a macro's expansion, or in another file)"});
        }
      }
      context.Report(std::move(diagnostic));
    }
  }
};

}  // namespace

const rule::Rule& TypingIntExpressionForFloatRule() {
  static const IntExpressionForFloatRule rule;
  return rule;
}

}  // namespace shaderport::rules
