// webgl/index-expression: indexing that GLSL ES 1.00 Appendix A does not require
// implementations to support, which WebGL therefore rejects for GLSL ES 1.00 code.
// An index must be a constant-index-expression (constants and for-loop indices,
// no function calls), except on uniforms in a vertex shader.
//
//   uniform int k;  ...  v[k]          // error in a fragment shader
//   for (int i = 0; i < 4; i++) a[i];  // fine: a loop index
#include <string>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/appendix_a.h"
#include "rules/webgl/constant_expression.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/index-expression";

// The variable an lvalue-like chain `a.b[1].c` starts from.
const glsl::Symbol* RootVariable(const rule::RuleContext& context, const glsl::Expr* expr) {
  while (expr != nullptr) {
    if (const auto* index = expr->As<glsl::IndexExpr>()) {
      expr = index->base;
    } else if (const auto* member = expr->As<glsl::MemberExpr>()) {
      expr = member->object;
    } else if (const auto* paren = expr->As<glsl::ParenExpr>()) {
      expr = paren->inner;
    } else {
      break;
    }
  }
  if (expr == nullptr || expr->kind != glsl::NodeKind::kIdentifierExpr) return nullptr;
  return webgl::SymbolOf(context, *expr);
}

bool IsUniform(const rule::RuleContext& context, const glsl::Symbol& symbol) {
  if (symbol.declaration == glsl::kNoNode || symbol.declaration >= context.Tree().NodeCount()) {
    return symbol.predeclared;  // e.g. a harness's uniforms
  }
  // A declarator's qualifiers live on its declaration: find it among the globals.
  for (const glsl::Node* node : context.Tree().Root()->declarations) {
    const auto* variable = node->As<glsl::VariableDeclaration>();
    if (variable == nullptr) continue;
    for (const glsl::Declarator* declarator : variable->declarators) {
      if (declarator->id == symbol.declaration) {
        return variable->qualifiers.Has(glsl::QualifierKind::kUniform);
      }
    }
  }
  return false;
}

class IndexExpressionRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "An index that is not a constant-index-expression in GLSL ES 1.00 (Appendix A)",
        "uniform int k;\n... colors[k] ...", "", rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    if (!webgl::AppendixAApplies(context)) return;
    const std::set<uint32_t> loop_indices = webgl::LoopIndices(context);
    const webgl::ConstantRules rules{100, &loop_indices};
    const bool vertex = !webgl::IsFragment(context);
    glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, uint32_t) {
      const auto* index = node.As<glsl::IndexExpr>();
      if (index == nullptr || index->index == nullptr ||
          index->index->kind == glsl::NodeKind::kErrorExpr) {
        return true;
      }
      if (webgl::IsConstantExpression(context.Model(), *index->index, rules)) return true;
      if (vertex) {
        const glsl::Symbol* root = RootVariable(context, index->base);
        if (root != nullptr && IsUniform(context, *root)) return true;
      }
      webgl::ReportError(context, kId, index->index->range,
                         "index expressions in GLSL ES 1.00 in WebGL may only use constants "
                         "and for-loop indices" +
                             std::string(vertex ? " (uniform arrays excepted)" : ""),
                         "GLSL ES 1.00 Appendix A section 5; GLSL ES 3.00 (WebGL 2 with "
                         "'#version 300 es') allows any index");
      return true;
    });
  }
};

}  // namespace

const rule::Rule& WebglIndexExpressionRule() {
  static const IndexExpressionRule rule;
  return rule;
}

}  // namespace shaderport::rules
