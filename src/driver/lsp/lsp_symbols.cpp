#include "driver/lsp/lsp_symbols.h"

#include <algorithm>
#include <set>
#include <vector>

#include "driver/dialect.h"
#include "driver/lsp/lsp_text.h"
#include "glsl/sema/builtins.h"
#include "rule/fix_engine.h"
#include "rules/shadertoy/builtin_dialects.h"

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
  const model::Stage stage = kind.stage;
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

// The node naming something at byte `at`: an identifier, or a called function's name.
std::optional<uint32_t> NameAt(const glsl::SyntaxTree& tree, FileId file, uint32_t at) {
  const auto contains = [&](const SourceRange& range) {
    return range.file == file && range.begin <= at && at <= range.end;
  };
  for (uint32_t id = 0; id < tree.NodeCount(); ++id) {
    const glsl::Node& node = tree.NodeAt(id);
    const auto* call = node.As<glsl::CallExpr>();
    if ((node.As<glsl::IdentifierExpr>() != nullptr && contains(node.range)) ||
        (call != nullptr && call->call_kind == glsl::CallKind::kFunction &&
         contains(call->callee.range))) {
      return id;
    }
  }
  return std::nullopt;
}

std::string NameOf(const glsl::Node& node) {
  if (const auto* identifier = node.As<glsl::IdentifierExpr>()) return identifier->name;
  if (const auto* call = node.As<glsl::CallExpr>()) return call->callee.text;
  return "";
}

std::string Signature(const glsl::BuiltinFunction& overload) {
  std::string text = glsl::Spell(overload.return_type) + " " + overload.name + "(";
  for (size_t i = 0; i < overload.params.size(); ++i) {
    if (i > 0) text += ", ";
    const glsl::ParamQualifier q = overload.params[i].qualifier;
    if (q == glsl::ParamQualifier::kOut) text += "out ";
    if (q == glsl::ParamQualifier::kInOut) text += "inout ";
    text += glsl::Spell(overload.params[i].type);
  }
  return text + ")";
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
  const std::optional<uint32_t> node = NameAt(*tree, file, at);
  const uint32_t symbol = node ? model->SymbolAt(*node) : glsl::kNoSymbol;
  if (symbol == glsl::kNoSymbol || symbol >= model->symbols.size()) return std::nullopt;
  const glsl::Symbol& found = model->symbols[symbol];
  const uint32_t declaration =
      found.definition != glsl::kNoNode ? found.definition : found.declaration;
  if (declaration == glsl::kNoNode || declaration >= tree->NodeCount()) return std::nullopt;
  const std::optional<SourceRange> name = NameRangeOf(tree->NodeAt(declaration));
  if (!name || name->file != file || !name->Valid()) return std::nullopt;
  return RangeOf(text, analysed.shift, *name);
}

Json ReferenceRanges(const std::filesystem::path& path, const std::string& text, uint32_t offset,
                     bool with_declaration) {
  Json ranges = Json::array();
  const Analysed analysed = Analyse(path, text);
  const glsl::SyntaxTree* tree = analysed.shader.tree;
  const glsl::SemanticModel* model = analysed.shader.model;
  if (tree == nullptr || model == nullptr || offset < analysed.shift) return ranges;
  const FileId file = analysed.file->Id();
  const std::optional<uint32_t> node = NameAt(*tree, file, offset - analysed.shift);
  const uint32_t symbol = node ? model->SymbolAt(*node) : glsl::kNoSymbol;
  if (symbol == glsl::kNoSymbol || symbol >= model->symbols.size()) return ranges;
  const glsl::Symbol& found = model->symbols[symbol];
  if (with_declaration && found.declaration != glsl::kNoNode &&
      found.declaration < tree->NodeCount()) {
    const std::optional<SourceRange> name = NameRangeOf(tree->NodeAt(found.declaration));
    if (name && name->file == file && name->Valid()) {
      ranges.push_back(RangeOf(text, analysed.shift, *name));
    }
  }
  for (uint32_t id = 0; id < tree->NodeCount() && id < model->references.size(); ++id) {
    if (model->references[id] != symbol) continue;
    const glsl::Node& use = tree->NodeAt(id);
    const auto* call = use.As<glsl::CallExpr>();
    const SourceRange where = call != nullptr ? call->callee.range : use.range;
    if (where.file == file && where.Valid() && use.As<glsl::TypeSpecifier>() == nullptr) {
      ranges.push_back(RangeOf(text, analysed.shift, where));
    }
  }
  return ranges;
}

std::optional<std::string> HoverText(const std::filesystem::path& path, const std::string& text,
                                     uint32_t offset) {
  const Analysed analysed = Analyse(path, text);
  const glsl::SyntaxTree* tree = analysed.shader.tree;
  const glsl::SemanticModel* model = analysed.shader.model;
  if (tree == nullptr || model == nullptr || offset < analysed.shift) return std::nullopt;
  const std::optional<uint32_t> node = NameAt(*tree, analysed.file->Id(), offset - analysed.shift);
  if (!node) return std::nullopt;
  const std::string name = NameOf(tree->NodeAt(*node));
  const uint32_t symbol = model->SymbolAt(*node);
  if (symbol != glsl::kNoSymbol && symbol < model->symbols.size()) {
    const glsl::Symbol& found = model->symbols[symbol];
    switch (found.kind) {
      case glsl::SymbolKind::kFunction: {
        std::string signature = model->Spell(found.type) + " " + found.name + "(";
        for (size_t i = 0; i < found.parameters.size(); ++i) {
          signature += (i > 0 ? ", " : "") + model->Spell(found.parameters[i]);
        }
        return "```glsl\n" + signature + ")\n```";
      }
      case glsl::SymbolKind::kBuiltinFunction:
        break;  // the overloads below
      default:
        if (!found.predeclared) {
          const char* what = found.kind == glsl::SymbolKind::kParameter ? "parameter"
                             : found.scope == 0                         ? "global"
                                                                        : "local";
          return "```glsl\n" + std::string(found.is_const ? "const " : "") +
                 model->Spell(found.type) + " " + found.name + "\n```\n(" + what + ")";
        }
    }
  }
  // What the ShaderToy site provides (declared by the site, not in the document).
  if (const rule::HarnessDialect* site = rules::FindBuiltinDialect("shadertoy")) {
    if (const rule::ProvidedVariable* provided = site->FindProvided(name)) {
      return "```glsl\nuniform " + provided->type + " " + provided->name +
             "\n```\nProvided by shadertoy.com (declared by the site before the pass).";
    }
  }
  // Families expand to the same signature more than once (mix(genType, genType,
  // float) gives mix(float, float, float) again): each is listed once.
  std::vector<std::string> signatures;
  for (const glsl::BuiltinFunction* overload : glsl::BuiltinOverloads(name)) {
    if (!overload->AvailableIn(model->version, model->stage)) continue;
    std::string signature = Signature(*overload);
    if (std::find(signatures.begin(), signatures.end(), signature) == signatures.end()) {
      signatures.push_back(std::move(signature));
    }
  }
  const size_t total = signatures.size();
  const size_t shown = std::min<size_t>(total, 8);
  std::string overloads;
  for (size_t i = 0; i < shown; ++i) overloads += signatures[i] + "\n";
  if (total == 0) return std::nullopt;
  std::string hover = "```glsl\n" + overloads + "```";
  if (total > shown) hover += "\n(" + std::to_string(total - shown) + " more overloads)";
  return hover + "\nBuilt-in function of GLSL ES " + (model->version == 100 ? "1.00" : "3.00") +
         ".";
}

Json CompletionItems(const std::filesystem::path& path, const std::string& text) {
  // LSP CompletionItemKind values.
  constexpr int kFunctionItem = 3;
  constexpr int kVariableItem = 6;
  constexpr int kStructItem = 22;
  const Analysed analysed = Analyse(path, text);
  Json items = Json::array();
  std::set<std::string> seen;
  const auto add = [&](const std::string& label, int kind, const std::string& detail) {
    if (label.empty() || !seen.insert(label).second) return;
    items.push_back({{"label", label}, {"kind", kind}, {"detail", detail}});
  };
  const glsl::SemanticModel* model = analysed.shader.model;
  const int version = model != nullptr ? model->version : 300;
  const model::Stage stage = model != nullptr ? model->stage : model::Stage::kFragment;
  if (model != nullptr) {
    for (const glsl::Symbol& symbol : model->symbols) {
      if (symbol.predeclared || symbol.declaration == glsl::kNoNode) continue;
      switch (symbol.kind) {
        case glsl::SymbolKind::kFunction:
          add(symbol.name, kFunctionItem, model->Spell(symbol.type) + " " + symbol.name + "(...)");
          break;
        case glsl::SymbolKind::kStruct:
          add(symbol.name, kStructItem, "struct " + symbol.name);
          break;
        case glsl::SymbolKind::kVariable:
        case glsl::SymbolKind::kParameter:
          add(symbol.name, kVariableItem, model->Spell(symbol.type));
          break;
        default:
          break;
      }
    }
  }
  if (DetectKind(text, path).dialect == Dialect::kShaderToy) {
    if (const rule::HarnessDialect* site = rules::FindBuiltinDialect("shadertoy")) {
      for (const rule::ProvidedVariable& provided : site->provides) {
        add(provided.name, kVariableItem, "uniform " + provided.type + " (shadertoy.com)");
      }
    }
  }
  for (const glsl::BuiltinVariable& variable : glsl::AllBuiltinVariables()) {
    if (glsl::FindBuiltinVariable(variable.name, version, stage) == &variable) {
      add(variable.name, kVariableItem, glsl::Spell(variable.type) + " (built-in)");
    }
  }
  for (const glsl::BuiltinFunction& function : glsl::AllBuiltinFunctions()) {
    if (function.AvailableIn(version, stage) && function.extension.empty()) {
      add(function.name, kFunctionItem, Signature(function) + " (built-in)");
    }
  }
  return items;
}

}  // namespace shaderport::driver::lsp
