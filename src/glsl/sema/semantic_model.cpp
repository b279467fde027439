#include "glsl/sema/semantic_model.h"

#include "glsl/sema/analyzer.h"

namespace shaderport::glsl {

const Type& SemanticModel::TypeOf(uint32_t node) const {
  static const Type kUnknown = Type::Unknown();
  return node < expression_types.size() ? expression_types[node] : kUnknown;
}

uint32_t SemanticModel::SymbolAt(uint32_t node) const {
  if (node < references.size() && references[node] != kNoSymbol) return references[node];
  if (node < declarations.size()) return declarations[node];
  return kNoSymbol;
}

std::vector<uint32_t> SemanticModel::UsesOf(uint32_t symbol) const {
  std::vector<uint32_t> uses;
  for (uint32_t node = 0; node < references.size(); ++node) {
    if (references[node] == symbol) uses.push_back(node);
  }
  return uses;
}

std::vector<uint32_t> SemanticModel::FindSymbols(std::string_view name) const {
  std::vector<uint32_t> found;
  for (uint32_t id = 0; id < symbols.size(); ++id) {
    if (symbols[id].name == name) found.push_back(id);
  }
  return found;
}

SemanticModel Analyze(const SyntaxTree& tree, const AnalyzeOptions& options) {
  return Analyzer(tree, options).Run();
}

}  // namespace shaderport::glsl
