#include "rules/webgl/appendix_a.h"

#include "glsl/syntax/visit.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules::webgl {

bool AppendixAApplies(const rule::RuleContext& context) { return IsEssl100(context); }

std::set<uint32_t> LoopIndices(const rule::RuleContext& context) {
  std::set<uint32_t> indices;
  glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, uint32_t) {
    const auto* loop = node.As<glsl::ForStatement>();
    if (loop == nullptr || loop->init == nullptr) return true;
    const auto* declaration = loop->init->As<glsl::VariableDeclaration>();
    if (declaration == nullptr || declaration->declarators.size() != 1) return true;
    const uint32_t symbol = context.Model().SymbolAt(declaration->declarators[0]->id);
    if (symbol != glsl::kNoSymbol) indices.insert(symbol);
    return true;
  });
  return indices;
}

}  // namespace shaderport::rules::webgl
