// typing/float-index: a float used as an array, vector or matrix index becomes
// an int. GLSL ES indexes with integers only; `int(...)` truncates, as the
// author indexing with a float counter expects. A whole-number float literal is
// simply written as an int.
//
// Before:                         After:
//   weights[i]     (float i)        weights[int(i)]
//   v[1.0]                          v[1]
#include <cmath>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/typing/typing_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "typing/float-index";

// `2.0` -> "2"; nothing for a fraction or a value out of int range.
std::optional<std::string> IntSpelling(const glsl::Expr& index) {
  const auto* literal = index.As<glsl::LiteralExpr>();
  if (literal == nullptr || literal->literal_kind != glsl::LiteralKind::kFloat) return std::nullopt;
  const double v = literal->float_value;
  if (!(v >= 0.0 && v < 2147483648.0) || std::floor(v) != v) return std::nullopt;
  return std::to_string(static_cast<int64_t>(v));
}

class FloatIndexRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "Index arrays and vectors with ints, not floats",
                                     "float w = weights[f];", "float w = weights[int(f)];",
                                     rule::RuleScope::kAlways};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    if (context.Tree().Root() == nullptr) return;
    const glsl::SemanticModel& model = context.Model();
    glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, uint32_t) {
      const auto* index = node.As<glsl::IndexExpr>();
      if (index == nullptr || index->index == nullptr) return true;
      const glsl::Type& type = model.TypeOf(index->index->id);
      if (!type.IsFloating() || !type.IsScalar()) return true;
      const glsl::Expr& e = *index->index;
      auto diagnostic = typing::MakeDiagnostic(kId, Severity::kError, e.range,
                                               "index '" + std::string(context.TextOf(e.range)) +
                                                   "' is a float; GLSL ES indexes with ints");
      const SourceRange range = typing::WrittenRange(context, e);
      if (auto spelling = IntSpelling(e); spelling && typing::InThisFile(context, range)) {
        diagnostic.fixes.push_back({range, *spelling});
      } else {
        diagnostic.fixes = typing::WrapInCall(context, e, "int");
      }
      context.Report(std::move(diagnostic));
      return true;
    });
  }
};

}  // namespace

const rule::Rule& TypingFloatIndexRule() {
  static const FloatIndexRule rule;
  return rule;
}

}  // namespace shaderport::rules
