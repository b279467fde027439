// Float arithmetic in source order, as Chromium computes it. Without `precise`, Mesa's
// NIR treats float operations as inexact and regroups sums (it moves constants up
// addition chains: (a + b) + 1.0 becomes (a + 1.0) + b), which changes the last bit;
// hash noise and escape-time fractals turn that bit into another colour. Chromium
// (ANGLE + SwiftShader) adds left to right, as written. Mesa keeps every operation
// whose value reaches an `invariant` output exact, so the fragment outputs are
// declared invariant. Mesa follows data only, not control flow, so the escape count
// of a loop (`if (dot(z, z) > 4.0) { n = i; break; }`) would still be computed from
// regrouped sums: every branch and loop condition is also assigned to the render
// probe's spare channel (`(probe[2] = float(c)) != 0.0`, the same truth value; an
// index, not `.z`, since the user's code may `#define z`), which
// is an invariant output too, or a variable Mesa makes invariant because it is read
// into the colour output's alpha (render_probe.cpp).
#include "glsl/sema/language.h"
#include "glsl/syntax/visit.h"
#include "glsl/webgl_semantics/semantics_context.h"

namespace shaderport::glsl {

void KeepSourceOrderArithmetic(SemanticsContext& c) {
  if (c.options.vertex_stage || c.model.version < kEssl300) return;
  for (const Node* node : c.tree.Root()->declarations) {
    const auto* decl = node->As<VariableDeclaration>();
    if (decl == nullptr || !decl->qualifiers.Has(QualifierKind::kOut) ||
        decl->qualifiers.Has(QualifierKind::kInvariant)) {
      continue;
    }
    const auto span = c.edits.Span(*decl);
    if (!span) {
      ++c.result.skipped;
      continue;
    }
    c.edits.Insert(span->file, span->begin, "invariant ");
    ++c.result.invariant_outputs;
  }
}

void ExposeBranchConditions(SemanticsContext& c, std::string_view probe) {
  const std::string open = "((" + std::string(probe) + "[2] = float(";
  VisitPreorder(c.tree, [&](const Node& node, uint32_t) {
    const Node* condition = nullptr;
    if (const auto* branch = node.As<IfStatement>()) condition = branch->condition;
    if (const auto* loop = node.As<ForStatement>()) condition = loop->condition;
    if (const auto* loop = node.As<WhileStatement>()) condition = loop->condition;
    if (const auto* loop = node.As<DoWhileStatement>()) condition = loop->condition;
    // A condition that declares a variable (`while (bool b = ...)`) is left alone.
    if (condition == nullptr || !condition->IsExpr()) return true;
    const auto span = c.edits.Span(*condition);
    if (!span) {
      ++c.result.skipped;
      return true;
    }
    // Outermost: other transforms may already have wrapped the condition's first or
    // last operand at the same offsets.
    c.edits.InsertOutermost(span->file, span->begin, open);
    c.edits.Insert(span->file, span->end, ")) != 0.0)");
    ++c.result.exposed_conditions;
    return true;
  });
}

}  // namespace shaderport::glsl
