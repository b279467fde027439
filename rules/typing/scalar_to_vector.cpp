// typing/scalar-to-vector: a scalar that initializes, is assigned to or is
// returned as a vector or matrix becomes a constructor call. GLSL ES never
// widens a scalar implicitly; `vec3(x)` repeats it in every component (and
// `mat3(x)` puts it on the diagonal, as the author of `mat3 m = x;` expects).
//
// Before:                         After:
//   vec3 v = 1.0;                   vec3 v = vec3(1.0);
//   col = 0.5;   (col a vec4)       col = vec4(0.5);
//   return 0.0;  (in a vec2 f())    return vec2(0.0);
#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/typing/typing_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "typing/scalar-to-vector";

using glsl::Type;

struct Site {
  const glsl::Expr* expr;
  Type required;
  const char* where;
};

bool ScalarFits(const Type& scalar, const Type& target) {
  if (!scalar.IsScalar()) return false;
  return scalar.base == target.base ||
         (scalar.base == glsl::BaseType::kInt && target.base == glsl::BaseType::kFloat);
}

// The model records scalars for vectors; matrices are found here.
void AddMatrixSites(const rule::RuleContext& context, std::vector<Site>& sites) {
  const glsl::SemanticModel& model = context.Model();
  auto check = [&](const glsl::Expr* value, const Type& target, const char* where) {
    if (value != nullptr && target.IsMatrix() && ScalarFits(model.TypeOf(value->id), target)) {
      sites.push_back({value, target, where});
    }
  };
  glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, uint32_t) {
    if (const auto* d = node.As<glsl::Declarator>()) {
      const uint32_t symbol = model.SymbolAt(d->id);
      if (symbol != glsl::kNoSymbol && symbol < model.symbols.size()) {
        check(d->initializer, model.symbols[symbol].type, "in an initializer");
      }
    } else if (const auto* a = node.As<glsl::AssignmentExpr>();
               a != nullptr && a->op == glsl::AssignOp::kAssign) {
      check(a->rhs, model.TypeOf(a->lhs->id), "in an assignment");
    }
    return true;
  });
}

class ScalarToVectorRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "Build vectors and matrices from scalars explicitly",
                                     "vec3 v = 1.0;", "vec3 v = vec3(1.0);",
                                     rule::RuleScope::kAlways};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const glsl::SyntaxTree& tree = context.Tree();
    if (tree.Root() == nullptr) return;
    const glsl::SemanticModel& model = context.Model();
    std::vector<Site> sites;
    for (const glsl::TypeMismatch& m : model.mismatches) {
      if (m.kind != glsl::MismatchKind::kScalarForVector || m.node >= tree.NodeCount()) continue;
      if (const auto* e = tree.NodeAt(m.node).As<glsl::Expr>()) {
        sites.push_back({e, m.required, typing::DescribeContext(m.context)});
      }
    }
    AddMatrixSites(context, sites);
    for (const Site& site : sites) {
      const std::string required = model.Spell(site.required);
      auto diagnostic = typing::MakeDiagnostic(
          kId, Severity::kError, site.expr->range,
          "scalar '" + std::string(context.TextOf(site.expr->range)) + "' used as " + required +
              " " + site.where + "; write " + required + "(...)");
      diagnostic.fixes = typing::WrapInCall(context, *site.expr, required);
      context.Report(std::move(diagnostic));
    }
  }
};

}  // namespace

const rule::Rule& TypingScalarToVectorRule() {
  static const ScalarToVectorRule rule;
  return rule;
}

}  // namespace shaderport::rules
