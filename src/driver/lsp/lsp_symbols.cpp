#include "driver/lsp/lsp_symbols.h"

#include <algorithm>
#include <set>
#include <vector>

#include "driver/dialect.h"
#include "driver/lsp/lsp_text.h"
#include "glsl/sema/builtins.h"
#include "glsl/syntax/ast.h"
#include "model/shipped_dialects.h"
#include "rule/fix_engine.h"

namespace shaderport::driver::lsp {
namespace {

using Json = nlohmann::json;

// LSP SymbolKind values.
constexpr int kFunctionSymbol = 12;
constexpr int kVariableSymbol = 13;
constexpr int kConstantSymbol = 14;
constexpr int kStructSymbol = 23;

// Where the declaring node names the symbol.
std::optional<SourceRange> NameRangeOf(const glsl::Node& node) {
  if (const auto* declarator = node.As<glsl::Declarator>()) return declarator->name.range;
  if (const auto* parameter = node.As<glsl::ParameterDeclaration>()) return parameter->name.range;
  if (const auto* function = node.As<glsl::FunctionDeclaration>()) return function->name.range;
  if (const auto* structure = node.As<glsl::StructSpecifier>()) return structure->name.range;
  if (const auto* block = node.As<glsl::InterfaceBlock>()) return block->block_name.range;
  return std::nullopt;
}

// The text of the name a declaring node declares ("" for other nodes).
std::string DeclaredName(const glsl::Node& node) {
  if (const auto* declarator = node.As<glsl::Declarator>()) return declarator->name.text;
  if (const auto* parameter = node.As<glsl::ParameterDeclaration>()) return parameter->name.text;
  if (const auto* function = node.As<glsl::FunctionDeclaration>()) return function->name.text;
  if (const auto* structure = node.As<glsl::StructSpecifier>()) return structure->name.text;
  return "";
}

// The node naming something at byte `at`: an identifier, a called function's name, or
// the name a declaration declares.
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
    if (node.As<glsl::InterfaceBlock>() == nullptr) {
      const std::optional<SourceRange> name = NameRangeOf(node);
      if (name && name->Valid() && contains(*name)) return id;
    }
  }
  return std::nullopt;
}

std::string NameOf(const glsl::Node& node) {
  if (const auto* identifier = node.As<glsl::IdentifierExpr>()) return identifier->name;
  if (const auto* call = node.As<glsl::CallExpr>()) return call->callee.text;
  return DeclaredName(node);
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

Json Symbol(const CodeUnit& unit, const std::string& name, int kind, const SourceRange& whole,
            const SourceRange& selection) {
  return {{"name", name},
          {"kind", kind},
          {"range", unit.RangeOf(whole)},
          {"selectionRange", unit.RangeOf(selection)}};
}

bool Analysed(const CodeUnit& unit) {
  return unit.shader.tree != nullptr && unit.shader.model != nullptr &&
         unit.shader.tree->Root() != nullptr;
}

// The outline of one unit's global declarations.
Json UnitSymbols(const CodeUnit& unit) {
  Json symbols = Json::array();
  if (!Analysed(unit)) return symbols;
  const glsl::SyntaxTree& tree = *unit.shader.tree;
  const FileId file = unit.file->Id();
  const auto here = [&](const SourceRange& range) { return range.file == file && range.Valid(); };
  for (const glsl::Node* node : tree.Root()->declarations) {
    if (node == nullptr) continue;
    if (const auto* function = node->As<glsl::FunctionDeclaration>()) {
      if (function->body != nullptr && here(function->name.range) && here(node->range)) {
        symbols.push_back(
            Symbol(unit, function->name.text, kFunctionSymbol, node->range, function->name.range));
      }
      continue;
    }
    const auto* declaration = node->As<glsl::VariableDeclaration>();
    if (declaration == nullptr || !here(node->range)) continue;
    const glsl::StructSpecifier* structure =
        declaration->type != nullptr ? declaration->type->struct_def : nullptr;
    if (structure != nullptr && !structure->name.Empty() && here(structure->name.range)) {
      symbols.push_back(Symbol(unit, structure->name.text, kStructSymbol, structure->range,
                               structure->name.range));
    }
    const bool constant = declaration->qualifiers.Has(glsl::QualifierKind::kConst);
    for (const glsl::Declarator* declarator : declaration->declarators) {
      if (declarator == nullptr || declarator->name.Empty() || !here(declarator->name.range)) {
        continue;
      }
      symbols.push_back(Symbol(unit, declarator->name.text,
                               constant ? kConstantSymbol : kVariableSymbol, node->range,
                               declarator->name.range));
    }
  }
  return symbols;
}

// A symbol and the unit that declares it.
struct Resolved {
  const CodeUnit* unit = nullptr;
  uint32_t symbol = glsl::kNoSymbol;

  const glsl::Symbol& Get() const { return unit->shader.model->symbols[symbol]; }
};

// A global of `common` named `name` (the definition of a function when there is one).
std::optional<Resolved> CommonGlobal(const CodeUnit* common, const std::string& name) {
  if (common == nullptr || !Analysed(*common) || name.empty()) return std::nullopt;
  const glsl::SemanticModel& model = *common->shader.model;
  std::optional<Resolved> found;
  for (const uint32_t id : model.FindSymbols(name)) {
    const glsl::Symbol& symbol = model.symbols[id];
    if (symbol.scope != 0 || symbol.predeclared || symbol.declaration == glsl::kNoNode) continue;
    if (!found ||
        (symbol.definition != glsl::kNoNode && found->Get().definition == glsl::kNoNode)) {
      found = Resolved{common, id};
    }
  }
  return found;
}

// What the name node `node` of `unit` refers to: a symbol of the unit, else (a name
// the unit does not declare) a global of the Common it sees.
std::optional<Resolved> Resolve(const ProjectCode& code, const CodeUnit& unit, uint32_t node) {
  const glsl::SemanticModel& model = *unit.shader.model;
  const uint32_t symbol = model.SymbolAt(node);
  if (symbol != glsl::kNoSymbol && symbol < model.symbols.size()) {
    const glsl::Symbol& found = model.symbols[symbol];
    if (found.declaration != glsl::kNoNode || found.kind == glsl::SymbolKind::kBuiltinFunction ||
        found.kind == glsl::SymbolKind::kBuiltinVariable || found.predeclared) {
      return Resolved{&unit, symbol};
    }
  }
  if (std::optional<Resolved> common =
          CommonGlobal(code.CommonOf(unit), NameOf(unit.shader.tree->NodeAt(node)))) {
    return common;
  }
  if (symbol != glsl::kNoSymbol && symbol < model.symbols.size()) return Resolved{&unit, symbol};
  return std::nullopt;
}

// The unit and name node at byte `offset` of the document.
struct NameHere {
  const CodeUnit* unit = nullptr;
  uint32_t node = glsl::kNoNode;
};
std::optional<NameHere> NameHereAt(const ProjectCode& code, uint32_t offset) {
  const auto at = code.At(offset);
  if (!at || !Analysed(*at->first)) return std::nullopt;
  const std::optional<uint32_t> node =
      NameAt(*at->first->shader.tree, at->first->file->Id(), at->second);
  if (!node) return std::nullopt;
  return NameHere{at->first, *node};
}

std::optional<SourceRange> DeclaredNameRange(const Resolved& resolved) {
  const glsl::Symbol& found = resolved.Get();
  const uint32_t declaration =
      found.definition != glsl::kNoNode ? found.definition : found.declaration;
  const glsl::SyntaxTree& tree = *resolved.unit->shader.tree;
  if (declaration == glsl::kNoNode || declaration >= tree.NodeCount()) return std::nullopt;
  const std::optional<SourceRange> name = NameRangeOf(tree.NodeAt(declaration));
  if (!name || name->file != resolved.unit->file->Id() || !name->Valid()) return std::nullopt;
  return name;
}

// Where a use names its symbol (a call: the callee), when in the unit's own code.
std::optional<SourceRange> UseRange(const CodeUnit& unit, const glsl::Node& use) {
  if (use.As<glsl::TypeSpecifier>() != nullptr) return std::nullopt;
  const auto* call = use.As<glsl::CallExpr>();
  const SourceRange where = call != nullptr ? call->callee.range : use.range;
  if (where.file != unit.file->Id() || !where.Valid()) return std::nullopt;
  return where;
}

}  // namespace

Json DocumentSymbols(const ProjectCode& code) {
  constexpr int kModuleSymbol = 2;
  Json symbols = Json::array();
  size_t passes = 0;
  for (const CodeUnit& unit : code.units) passes += unit.in_document ? 1 : 0;
  for (const CodeUnit& unit : code.units) {
    if (!unit.in_document) continue;
    Json own = UnitSymbols(unit);
    if (passes == 1 && unit.shown_offsets.empty()) return own;
    // A pass of a JSON project: its code string holds its declarations.
    const std::string name = unit.file->Name().substr(unit.file->Name().rfind('#') + 1);
    const SourceRange whole{unit.file->Id(), 0, static_cast<uint32_t>(unit.file->Text().size())};
    Json pass = Symbol(unit, name, kModuleSymbol, whole, {unit.file->Id(), 0, 0});
    pass["children"] = std::move(own);
    symbols.push_back(std::move(pass));
  }
  return symbols;
}

std::optional<Json> DefinitionLocation(const ProjectCode& code, uint32_t offset) {
  const std::optional<NameHere> here = NameHereAt(code, offset);
  if (!here) return std::nullopt;
  const std::optional<Resolved> resolved = Resolve(code, *here->unit, here->node);
  if (!resolved) return std::nullopt;
  const std::optional<SourceRange> name = DeclaredNameRange(*resolved);
  if (!name) return std::nullopt;
  return resolved->unit->LocationOf(*name);
}

Json ReferenceLocations(const ProjectCode& code, uint32_t offset, bool with_declaration) {
  Json locations = Json::array();
  const std::optional<NameHere> here = NameHereAt(code, offset);
  if (!here) return locations;
  const std::optional<Resolved> resolved = Resolve(code, *here->unit, here->node);
  if (!resolved || resolved->Get().declaration == glsl::kNoNode) return locations;
  const CodeUnit& declaring = *resolved->unit;
  const glsl::Symbol& symbol = resolved->Get();
  if (with_declaration) {
    const glsl::SyntaxTree& tree = *declaring.shader.tree;
    if (symbol.declaration < tree.NodeCount()) {
      const std::optional<SourceRange> name = NameRangeOf(tree.NodeAt(symbol.declaration));
      if (name && name->file == declaring.file->Id() && name->Valid()) {
        locations.push_back(declaring.LocationOf(*name));
      }
    }
  }
  for (const uint32_t id : declaring.shader.model->UsesOf(resolved->symbol)) {
    if (const auto where = UseRange(declaring, declaring.shader.tree->NodeAt(id))) {
      locations.push_back(declaring.LocationOf(*where));
    }
  }
  // A global of Common: the passes that see it use it under its name, undeclared there.
  if (!declaring.common || symbol.scope != 0) return locations;
  for (const CodeUnit& unit : code.units) {
    if (&unit == &declaring || code.CommonOf(unit) != &declaring || !Analysed(unit)) continue;
    const glsl::SyntaxTree& tree = *unit.shader.tree;
    const glsl::SemanticModel& model = *unit.shader.model;
    for (uint32_t id = 0; id < tree.NodeCount(); ++id) {
      const glsl::Node& use = tree.NodeAt(id);
      const auto* call = use.As<glsl::CallExpr>();
      const bool name_use = use.As<glsl::IdentifierExpr>() != nullptr ||
                            (call != nullptr && call->call_kind == glsl::CallKind::kFunction);
      if (!name_use || NameOf(use) != symbol.name) continue;
      const uint32_t local = model.SymbolAt(id);
      if (local != glsl::kNoSymbol && local < model.symbols.size() &&
          model.symbols[local].declaration != glsl::kNoNode) {
        continue;  // the pass's own declaration of that name
      }
      if (const auto where = UseRange(unit, use)) locations.push_back(unit.LocationOf(*where));
    }
  }
  return locations;
}

namespace {

std::string DeclaredHover(const glsl::SemanticModel& model, const glsl::Symbol& found,
                          bool from_common) {
  const std::string origin = from_common ? " in Common" : "";
  if (found.kind == glsl::SymbolKind::kFunction) {
    std::string signature = model.Spell(found.type) + " " + found.name + "(";
    for (size_t i = 0; i < found.parameters.size(); ++i) {
      signature += (i > 0 ? ", " : "") + model.Spell(found.parameters[i]);
    }
    return "```glsl\n" + signature + ")\n```" + (from_common ? "\n(declared in Common)" : "");
  }
  const char* what = found.kind == glsl::SymbolKind::kParameter ? "parameter"
                     : found.scope == 0                         ? "global"
                                                                : "local";
  return "```glsl\n" + std::string(found.is_const ? "const " : "") + model.Spell(found.type) + " " +
         found.name + "\n```\n(" + what + origin + ")";
}

std::string BuiltinHover(const glsl::SemanticModel& model, const std::string& name) {
  // Families expand to the same signature more than once (mix(genType, genType,
  // float) gives mix(float, float, float) again): each is listed once.
  std::vector<std::string> signatures;
  for (const glsl::BuiltinFunction* overload : glsl::BuiltinOverloads(name)) {
    if (!overload->AvailableIn(model.version, model.stage)) continue;
    std::string signature = Signature(*overload);
    if (std::find(signatures.begin(), signatures.end(), signature) == signatures.end()) {
      signatures.push_back(std::move(signature));
    }
  }
  const size_t total = signatures.size();
  if (total == 0) return "";
  const size_t shown = std::min<size_t>(total, 8);
  std::string overloads;
  for (size_t i = 0; i < shown; ++i) overloads += signatures[i] + "\n";
  std::string hover = "```glsl\n" + overloads + "```";
  if (total > shown) hover += "\n(" + std::to_string(total - shown) + " more overloads)";
  return hover + "\nBuilt-in function of GLSL ES " + (model.version == 100 ? "1.00" : "3.00") + ".";
}

// The innermost expression around code offset `at` that has a type.
std::optional<std::string> ExpressionHover(const CodeUnit& unit, uint32_t at) {
  const glsl::SyntaxTree& tree = *unit.shader.tree;
  const glsl::SemanticModel& model = *unit.shader.model;
  const FileId file = unit.file->Id();
  std::optional<uint32_t> best;
  for (uint32_t id = 0; id < tree.NodeCount() && id < model.expression_types.size(); ++id) {
    const glsl::Node& node = tree.NodeAt(id);
    if (!node.IsExpr() || node.range.file != file || node.range.begin > at ||
        at >= node.range.end || model.TypeOf(id).IsUnknown()) {
      continue;
    }
    if (!best || node.range.Size() < tree.NodeAt(*best).range.Size()) best = id;
  }
  if (!best) return std::nullopt;
  const SourceRange& range = tree.NodeAt(*best).range;
  std::string text(unit.file->Text().substr(range.begin, range.Size()));
  if (text.size() > 60 || text.find('\n') != std::string::npos) text = "(expression)";
  return "```glsl\n" + model.Spell(model.TypeOf(*best)) + "\n```\nthe type of `" + text + "`";
}

}  // namespace

std::optional<std::string> HoverText(const ProjectCode& code, uint32_t offset,
                                     const std::vector<std::string>& channel_kinds) {
  const auto at = code.At(offset);
  if (!at || !Analysed(*at->first)) return std::nullopt;
  const CodeUnit& unit = *at->first;
  const glsl::SemanticModel& model = *unit.shader.model;
  const std::optional<uint32_t> node = NameAt(*unit.shader.tree, unit.file->Id(), at->second);
  if (!node) return ExpressionHover(unit, at->second);
  const std::string name = NameOf(unit.shader.tree->NodeAt(*node));
  if (const std::optional<Resolved> resolved = Resolve(code, unit, *node)) {
    const glsl::Symbol& found = resolved->Get();
    const bool declared = !found.predeclared && found.kind != glsl::SymbolKind::kBuiltinFunction &&
                          found.kind != glsl::SymbolKind::kBuiltinVariable;
    if (declared)
      return DeclaredHover(*resolved->unit->shader.model, found, resolved->unit != &unit);
  }
  // What the ShaderToy site provides (declared by the site, not in the document).
  if (const model::HarnessDialect* site = model::FindBuiltinDialect("shadertoy")) {
    if (const model::ProvidedVariable* provided = site->FindProvided(name)) {
      std::string type = provided->type;
      std::string checked_as;
      if (provided->channel >= 0 && static_cast<size_t>(provided->channel) < channel_kinds.size()) {
        const std::string& kind = channel_kinds[provided->channel];
        type = kind == "cube" ? "samplerCube" : kind == "3d" ? "sampler3D" : "sampler2D";
        checked_as = "\n\nChecked as a " + type + " (the sampler type check gave this channel).";
      }
      std::string hover =
          "```glsl\nuniform " + type + " " + provided->name +
          "\n```\nProvided by shadertoy.com (declared by the site before the pass).";
      if (!provided->description.empty()) hover += "\n\n" + provided->description;
      return hover + checked_as;
    }
  }
  if (std::string builtin = BuiltinHover(model, name); !builtin.empty()) return builtin;
  return ExpressionHover(unit, at->second);
}

namespace {

// The innermost scope of `unit` whose opening node holds code offset `at`.
uint32_t ScopeAt(const CodeUnit& unit, uint32_t at) {
  const glsl::SemanticModel& model = *unit.shader.model;
  const glsl::SyntaxTree& tree = *unit.shader.tree;
  uint32_t best = 0;
  uint32_t best_size = UINT32_MAX;
  for (uint32_t id = 1; id < model.scopes.size(); ++id) {
    const uint32_t node = model.scopes[id].node;
    if (node == glsl::kNoNode || node >= tree.NodeCount()) continue;
    const SourceRange& range = tree.NodeAt(node).range;
    if (range.file == unit.file->Id() && range.begin <= at && at <= range.end &&
        range.Size() < best_size) {
      best = id;
      best_size = range.Size();
    }
  }
  return best;
}

bool Encloses(const glsl::SemanticModel& model, uint32_t outer, uint32_t inner) {
  for (uint32_t scope = inner; scope != glsl::kNoScope && scope < model.scopes.size();
       scope = model.scopes[scope].parent) {
    if (scope == outer) return true;
  }
  return false;
}

}  // namespace

Json CompletionItems(const ProjectCode& code, uint32_t offset) {
  // LSP CompletionItemKind values.
  constexpr int kFunctionItem = 3;
  constexpr int kVariableItem = 6;
  constexpr int kStructItem = 22;
  Json items = Json::array();
  std::set<std::string> seen;
  const auto add = [&](const std::string& label, int kind, const std::string& detail) {
    if (label.empty() || !seen.insert(label).second) return;
    items.push_back({{"label", label}, {"kind", kind}, {"detail", detail}});
  };
  const auto at = code.At(offset);
  const CodeUnit* unit = at ? at->first : nullptr;
  const glsl::SemanticModel* model =
      unit != nullptr && Analysed(*unit) ? unit->shader.model : nullptr;
  // A unit's declarations visible at code offset `where` (all globals: UINT32_MAX).
  const auto add_declared = [&](const CodeUnit& from, uint32_t where, const std::string& origin) {
    const glsl::SemanticModel& declared = *from.shader.model;
    const glsl::SyntaxTree& tree = *from.shader.tree;
    const uint32_t scope = where == UINT32_MAX ? 0 : ScopeAt(from, where);
    for (const glsl::Symbol& symbol : declared.symbols) {
      if (symbol.predeclared || symbol.declaration == glsl::kNoNode ||
          symbol.declaration >= tree.NodeCount() || !Encloses(declared, symbol.scope, scope)) {
        continue;
      }
      if (tree.NodeAt(symbol.declaration).range.begin > where) continue;  // declared later
      switch (symbol.kind) {
        case glsl::SymbolKind::kFunction:
          add(symbol.name, kFunctionItem,
              declared.Spell(symbol.type) + " " + symbol.name + "(...)" + origin);
          break;
        case glsl::SymbolKind::kStruct:
          add(symbol.name, kStructItem, "struct " + symbol.name + origin);
          break;
        case glsl::SymbolKind::kVariable:
        case glsl::SymbolKind::kParameter:
          add(symbol.name, kVariableItem, declared.Spell(symbol.type) + origin);
          break;
        default:
          break;
      }
    }
  };
  if (model != nullptr) add_declared(*unit, at->second, "");
  if (unit != nullptr) {
    if (const CodeUnit* common = code.CommonOf(*unit); common != nullptr && Analysed(*common)) {
      add_declared(*common, UINT32_MAX, " (Common)");
    }
  }
  const int version = model != nullptr ? model->version : 300;
  const model::Stage stage = model != nullptr ? model->stage : model::Stage::kFragment;
  const bool shadertoy =
      unit != nullptr &&
      (!unit->shown_offsets.empty() ||
       DetectKind(unit->file->Text(), unit->file->Name()).dialect == Dialect::kShaderToy);
  if (shadertoy) {
    if (const model::HarnessDialect* site = model::FindBuiltinDialect("shadertoy")) {
      for (const model::ProvidedVariable& provided : site->provides) {
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
