#include "driver/lsp/lsp_symbols.h"

#include "driver/dialect.h"
#include "driver/lsp/lsp_text.h"
#include "rule/fix_engine.h"

namespace shaderport::driver::lsp {
namespace {

using Json = nlohmann::json;

// LSP SymbolKind values.
constexpr int kFunctionSymbol = 12;
constexpr int kVariableSymbol = 13;
constexpr int kConstantSymbol = 14;
constexpr int kStructSymbol = 23;

// The document analysed alone; offsets of its tree are offsets of `text` past the
// byte order mark (`shift`).
struct Analysed {
  std::unique_ptr<SourceFile> file;
  rule::AnalyzedShader shader;
  uint32_t shift = 0;
};

Analysed Analyse(const std::filesystem::path& path, const std::string& text) {
  Analysed out;
  out.shift = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
  std::string body = text.substr(out.shift);
  const DetectedKind kind = DetectKind(body, path);
  out.file = std::make_unique<SourceFile>(0, path.string(), std::move(body));
  const int version = kind.dialect == Dialect::kWebGL1 ? 100 : 300;
  const rule::ShaderStage stage =
      kind.stage == Stage::kVertex ? rule::ShaderStage::kVertex : rule::ShaderStage::kFragment;
  out.shader = rule::AnalyzePlain(*out.file, version, stage);
  return out;
}

Json RangeOf(const std::string& text, uint32_t shift, const SourceRange& range) {
  return {{"start", ToJson(PositionOf(text, range.begin + shift))},
          {"end", ToJson(PositionOf(text, range.end + shift))}};
}

Json Symbol(const std::string& text, uint32_t shift, const std::string& name, int kind,
            const SourceRange& whole, const SourceRange& selection) {
  return {{"name", name},
          {"kind", kind},
          {"range", RangeOf(text, shift, whole)},
          {"selectionRange", RangeOf(text, shift, selection)}};
}

// Where the declaring node names the symbol.
std::optional<SourceRange> NameRangeOf(const glsl::Node& node) {
  if (const auto* declarator = node.As<glsl::Declarator>()) return declarator->name.range;
  if (const auto* parameter = node.As<glsl::ParameterDeclaration>()) return parameter->name.range;
  if (const auto* function = node.As<glsl::FunctionDeclaration>()) return function->name.range;
  if (const auto* structure = node.As<glsl::StructSpecifier>()) return structure->name.range;
  if (const auto* block = node.As<glsl::InterfaceBlock>()) return block->block_name.range;
  return std::nullopt;
}

}  // namespace

Json DocumentSymbols(const std::filesystem::path& path, const std::string& text) {
  Json symbols = Json::array();
  const Analysed analysed = Analyse(path, text);
  const glsl::SyntaxTree* tree = analysed.shader.tree;
  if (tree == nullptr || tree->Root() == nullptr) return symbols;
  const FileId file = analysed.file->Id();
  const auto here = [&](const SourceRange& range) { return range.file == file && range.Valid(); };
  for (const glsl::Node* node : tree->Root()->declarations) {
    if (node == nullptr) continue;
    if (const auto* function = node->As<glsl::FunctionDeclaration>()) {
      if (function->body != nullptr && here(function->name.range) && here(node->range)) {
        symbols.push_back(Symbol(text, analysed.shift, function->name.text, kFunctionSymbol,
                                 node->range, function->name.range));
      }
      continue;
    }
    const auto* declaration = node->As<glsl::VariableDeclaration>();
    if (declaration == nullptr || !here(node->range)) continue;
    const glsl::StructSpecifier* structure =
        declaration->type != nullptr ? declaration->type->struct_def : nullptr;
    if (structure != nullptr && !structure->name.Empty() && here(structure->name.range)) {
      symbols.push_back(Symbol(text, analysed.shift, structure->name.text, kStructSymbol,
                               structure->range, structure->name.range));
    }
    const bool constant = declaration->qualifiers.Has(glsl::QualifierKind::kConst);
    for (const glsl::Declarator* declarator : declaration->declarators) {
      if (declarator == nullptr || declarator->name.Empty() || !here(declarator->name.range)) {
        continue;
      }
      symbols.push_back(Symbol(text, analysed.shift, declarator->name.text,
                               constant ? kConstantSymbol : kVariableSymbol, node->range,
                               declarator->name.range));
    }
  }
  return symbols;
}

std::optional<Json> DefinitionRange(const std::filesystem::path& path, const std::string& text,
                                    uint32_t offset) {
  const Analysed analysed = Analyse(path, text);
  const glsl::SyntaxTree* tree = analysed.shader.tree;
  const glsl::SemanticModel* model = analysed.shader.model;
  if (tree == nullptr || model == nullptr || offset < analysed.shift) return std::nullopt;
  const uint32_t at = offset - analysed.shift;
  const FileId file = analysed.file->Id();
  const auto contains = [&](const SourceRange& range) {
    return range.file == file && range.begin <= at && at <= range.end;
  };
  // The name under the cursor: an identifier, or the name of a called function.
  uint32_t symbol = glsl::kNoSymbol;
  for (uint32_t id = 0; id < tree->NodeCount() && symbol == glsl::kNoSymbol; ++id) {
    const glsl::Node& node = tree->NodeAt(id);
    const auto* identifier = node.As<glsl::IdentifierExpr>();
    const auto* call = node.As<glsl::CallExpr>();
    const bool named = (identifier != nullptr && contains(node.range)) ||
                       (call != nullptr && call->call_kind == glsl::CallKind::kFunction &&
                        contains(call->callee.range));
    if (named) symbol = model->SymbolAt(id);
  }
  if (symbol == glsl::kNoSymbol || symbol >= model->symbols.size()) return std::nullopt;
  const glsl::Symbol& found = model->symbols[symbol];
  const uint32_t declaration =
      found.definition != glsl::kNoNode ? found.definition : found.declaration;
  if (declaration == glsl::kNoNode || declaration >= tree->NodeCount()) return std::nullopt;
  const std::optional<SourceRange> name = NameRangeOf(tree->NodeAt(declaration));
  if (!name || name->file != file || !name->Valid()) return std::nullopt;
  return RangeOf(text, analysed.shift, *name);
}

}  // namespace shaderport::driver::lsp
