// typing/int-literal-for-float: an int literal where a float is required becomes
// a float literal. GLSL ES converts nothing implicitly, so `1` beside a float is
// an error in browsers and glslang alike; `1.0` means what the author meant.
//
// Before:                         After:
//   float x = 1;                    float x = 1.0;
//   if (t > 0) ...                  if (t > 0.0) ...
//   pow(x, 2); -3 * y               pow(x, 2.0); -3.0 * y
//   float h = 0x10;                 float h = 16.0;
#include "rules/all_rules.h"
#include "rules/typing/typing_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "typing/int-literal-for-float";

class IntLiteralForFloatRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "Write int literals used as floats as float literals",
                                     "float x = 1;\nbool b = x > 0;",
                                     "float x = 1.0;\nbool b = x > 0.0;", rule::RuleScope::kAlways};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    for (const typing::IntForFloatSite& site : typing::IntForFloatSites(context)) {
      const glsl::LiteralExpr* literal = typing::AsIntLiteral(site.expr);
      if (literal == nullptr) continue;  // typing/int-expression-for-float
      const std::string required = context.Model().Spell(site.required);
      auto diagnostic = typing::MakeDiagnostic(
          kId, Severity::kError, site.expr->range,
          "int literal '" + literal->text + "' used as " + required + " " + site.where +
              "; GLSL ES has no implicit int-to-float conversion");
      const std::optional<std::string> spelling = typing::FloatSpelling(*literal);
      const SourceRange range = typing::WrittenRange(context, *literal);
      if (!site.not_fixable_note.empty()) {
        diagnostic.notes.push_back({{}, site.not_fixable_note});
      } else if (spelling && typing::InThisFile(context, range) && site.required.IsScalar()) {
        diagnostic.fixes.push_back({range, *spelling, FixSafety::kSafe});
      }
      context.Report(std::move(diagnostic));
    }
  }
};

}  // namespace

const rule::Rule& TypingIntLiteralForFloatRule() {
  static const IntLiteralForFloatRule rule;
  return rule;
}

}  // namespace shaderport::rules
