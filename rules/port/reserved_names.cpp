// port/reserved-names: user names that GLSL ES 3.00 reserves (`sample`, `layout`,
// `smooth`, `uint`, `filter`, ... every keyword and reserved word of the spec, see
// src/glsl/syntax/keywords.def) or that hide an ES 3.00 built-in function
// (`texture`, `round`, ...: rules/data/webgl2_new_builtin_functions.def) are renamed
// at the declaration and every use, to a fresh name (`sample_`, `texture_`, ...).
// User functions named like any ES 3.00 built-in (`transpose`, `mod` overloads) are
// renamed too: ES 3.00 forbids redeclaring or overloading built-in functions.
//
// Before:                               After:
//   uniform sampler2D texture;            uniform sampler2D texture_;
//   float sample = texture2D(texture,     float sample_ = texture2D(texture_,
//                            uv).r;                                 uv).r;
//
// Runs when porting, and when fixing GLSL ES 3.00 code in its own dialect (there
// only for names that are errors: reserved words and functions named like
// built-ins). Names are picked from the old name alone when free, so a vertex and
// a fragment shader rename a shared varying the same way.
#include <set>
#include <string>

#include "glsl/sema/builtins.h"
#include "glsl/syntax/keywords.h"
#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/port/port_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "port/reserved-names";

bool ReservedIn300(std::string_view name) {
  return glsl::ClassifyWord(name, 300).status != glsl::WordStatus::kIdentifier;
}

bool NewBuiltinFunction(std::string_view name) {
  static const std::set<std::string_view> kNames = {
#define NEW_BUILTIN(name) #name,
#include "rules/data/webgl2_new_builtin_functions.def"
#undef NEW_BUILTIN
  };
  return kNames.contains(name);
}

bool Es300BuiltinFunction(std::string_view name) {
  for (const glsl::BuiltinFunction* overload : glsl::BuiltinOverloads(name)) {
    if ((overload->versions & glsl::kVersion300) != 0) return true;
  }
  return false;
}

// The range of the name a node declares or uses, if it has one.
std::optional<SourceRange> NameRange(const glsl::Node& node, std::string_view name) {
  if (node.kind == glsl::NodeKind::kIdentifierExpr) return node.range;
  if (const auto* call = node.As<glsl::CallExpr>()) return call->callee.range;
  if (const auto* type = node.As<glsl::TypeSpecifier>()) return type->name.range;
  if (const auto* declarator = node.As<glsl::Declarator>()) return declarator->name.range;
  if (const auto* parameter = node.As<glsl::ParameterDeclaration>()) return parameter->name.range;
  if (const auto* function = node.As<glsl::FunctionDeclaration>()) return function->name.range;
  if (const auto* structure = node.As<glsl::StructSpecifier>()) return structure->name.range;
  if (const auto* block = node.As<glsl::InterfaceBlock>()) {
    if (block->instance_name.text == name) return block->instance_name.range;
  }
  return std::nullopt;
}

class ReservedNamesRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "Rename user names that GLSL ES 3.00 reserves or that hide its built-ins",
        "uniform sampler2D texture;\nfloat sample = 1.0;",
        "uniform sampler2D texture_;\nfloat sample_ = 1.0;", rule::RuleScope::kAlways};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const bool porting = context.Settings().mode == rule::PortMode::kPort;
    if (!porting && context.Settings().source_version < 300) return;  // 1.00 stays 1.00
    RenameSymbols(context, porting);
    RenameStructFields(context);
  }

 private:
  static void RenameSymbols(rule::RuleContext& context, bool porting) {
    const auto& model = context.Model();
    const auto& tree = context.Tree();
    for (uint32_t symbol_id = 0; symbol_id < model.symbols.size(); ++symbol_id) {
      const glsl::Symbol& symbol = model.symbols[symbol_id];
      if (symbol.predeclared || symbol.declaration == glsl::kNoNode ||
          symbol.declaration >= tree.NodeCount()) {
        continue;
      }
      const bool function = symbol.kind == glsl::SymbolKind::kFunction;
      const bool data = symbol.kind == glsl::SymbolKind::kVariable ||
                        symbol.kind == glsl::SymbolKind::kParameter ||
                        symbol.kind == glsl::SymbolKind::kStruct;
      if (!function && !data) continue;
      const bool reserved = ReservedIn300(symbol.name);
      const bool hides =
          function ? Es300BuiltinFunction(symbol.name) : porting && NewBuiltinFunction(symbol.name);
      if (!reserved && !hides) continue;
      const glsl::Node& declaration = tree.NodeAt(symbol.declaration);
      if (!webgl2::InThisFile(context, declaration.range)) continue;
      Rename(context, symbol_id, reserved);
    }
  }

  static void Rename(rule::RuleContext& context, uint32_t symbol_id, bool reserved) {
    const auto& model = context.Model();
    const auto& tree = context.Tree();
    const glsl::Symbol& symbol = model.symbols[symbol_id];
    const std::string name = webgl2::FreshName(context, symbol.name + "_");
    const glsl::Node& declaration = tree.NodeAt(symbol.declaration);
    const std::optional<SourceRange> declared = NameRange(declaration, symbol.name);
    const SourceRange at = declared.value_or(declaration.range);
    const bool error = reserved && context.Settings().source_version >= 300;
    auto diagnostic = webgl2::MakeDiagnostic(
        kId, error ? Severity::kError : Severity::kWarning, at,
        "'" + symbol.name + "' " +
            (reserved ? "is a reserved word in GLSL ES 3.00"
                      : std::string(symbol.kind == glsl::SymbolKind::kFunction
                                        ? "redeclares a GLSL ES 3.00 built-in function"
                                        : "hides a GLSL ES 3.00 built-in function")) +
            "; renaming it to '" + name + "'");
    // Every node that names the symbol: declarations (prototypes too) and uses.
    std::set<std::pair<uint32_t, uint32_t>> seen;
    bool complete = declared.has_value();
    auto add = [&](const glsl::Node& node) {
      const auto range = NameRange(node, symbol.name);
      if (!range || !range->Valid()) {
        complete = false;
        return;
      }
      // A use written through a macro keeps its fix: Report() drops it with a note.
      if (!context.InMacro(*range) && context.TextOf(*range) != symbol.name) {
        complete = false;
        return;
      }
      // Deduplicated on where the name is spelled: every name expanded from one macro
      // shares the invocation's range, yet each has its own place in the body.
      const SourceRange spelled = webgl2::NameFixRange(context, node, *range, symbol.name);
      if (!seen.insert({spelled.begin, spelled.end}).second) return;
      diagnostic.fixes.push_back(webgl2::Replace(spelled, name));
    };
    add(declaration);
    for (uint32_t id = 0; id < tree.NodeCount(); ++id) {
      if (id != symbol.declaration && model.SymbolAt(id) == symbol_id &&
          tree.NodeAt(id).kind == glsl::NodeKind::kFunctionDeclaration) {
        add(tree.NodeAt(id));  // another prototype or the definition
      }
    }
    for (uint32_t use : model.UsesOf(symbol_id)) add(tree.NodeAt(use));
    if (!complete) diagnostic.fixes.clear();
    if (IsInterface(declaration, tree)) {
      diagnostic.notes.push_back(
          {at, "the host application must use the new name '" + name + "' for this input"});
    }
    webgl2::ReportSplittingMacroBodies(context, std::move(diagnostic));
  }

  // A global the host application sees by name: uniform, attribute, varying, in, out.
  static bool IsInterface(const glsl::Node& declaration, const glsl::SyntaxTree& tree) {
    if (declaration.kind == glsl::NodeKind::kInterfaceBlock) return true;
    if (declaration.kind != glsl::NodeKind::kDeclarator) return false;
    for (const glsl::Node* top : tree.Root()->declarations) {
      const auto* variable = top->As<glsl::VariableDeclaration>();
      if (variable == nullptr || !variable->range.Contains(declaration.range)) continue;
      for (const auto& qualifier : variable->qualifiers.items) {
        switch (qualifier.kind) {
          case glsl::QualifierKind::kUniform:
          case glsl::QualifierKind::kAttribute:
          case glsl::QualifierKind::kVarying:
          case glsl::QualifierKind::kIn:
          case glsl::QualifierKind::kOut:
            return true;
          default:
            break;
        }
      }
    }
    return false;
  }

  // Struct fields are not symbols: rename the field's declarator and every member
  // access whose object has that struct type.
  static void RenameStructFields(rule::RuleContext& context) {
    const auto& model = context.Model();
    const auto& tree = context.Tree();
    for (uint32_t struct_id = 0; struct_id < model.structs.Size(); ++struct_id) {
      const glsl::StructInfo& info = model.structs.Get(struct_id);
      if (info.declaration == glsl::kNoNode || info.declaration >= tree.NodeCount()) continue;
      const auto* specifier = tree.NodeAt(info.declaration).As<glsl::StructSpecifier>();
      if (specifier == nullptr || !webgl2::InThisFile(context, specifier->range)) continue;
      for (const glsl::VariableDeclaration* field : specifier->fields) {
        for (const glsl::Declarator* declarator : field->declarators) {
          if (declarator != nullptr && ReservedIn300(declarator->name.text)) {
            RenameField(context, struct_id, *declarator);
          }
        }
      }
    }
  }

  static void RenameField(rule::RuleContext& context, uint32_t struct_id,
                          const glsl::Declarator& field) {
    const auto& model = context.Model();
    const auto& tree = context.Tree();
    const std::string name = webgl2::FreshName(context, field.name.text + "_");
    auto diagnostic = webgl2::MakeDiagnostic(
        kId, context.Settings().source_version >= 300 ? Severity::kError : Severity::kWarning,
        field.name.range,
        "field '" + field.name.text + "' is a reserved word in GLSL ES 3.00; renaming it to '" +
            name + "'");
    diagnostic.fixes.push_back(webgl2::Replace(field.name.range, name));
    for (uint32_t id = 0; id < tree.NodeCount(); ++id) {
      const auto* member = tree.NodeAt(id).As<glsl::MemberExpr>();
      if (member == nullptr || member->object == nullptr ||
          member->member.text != field.name.text) {
        continue;
      }
      const glsl::Type& type = model.TypeOf(member->object->id);
      if (type.base == glsl::BaseType::kStruct && type.struct_id == struct_id) {
        diagnostic.fixes.push_back(webgl2::Replace(member->member.range, name));
      }
    }
    context.Report(std::move(diagnostic));
  }
};

}  // namespace

const rule::Rule& PortReservedNamesRule() {
  static const ReservedNamesRule rule;
  return rule;
}

}  // namespace shaderport::rules
