// The semantic model of one shader: scopes, symbols and their uses, the type of
// every expression, and the strict-typing mistakes (TypeMismatch) that rules fix.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "glsl/sema/builtins.h"
#include "glsl/sema/language.h"
#include "glsl/sema/struct_table.h"
#include "glsl/sema/type.h"
#include "glsl/syntax/ast.h"
#include "source/source_manager.h"

namespace shaderport::glsl {

inline constexpr uint32_t kNoSymbol = UINT32_MAX;
inline constexpr uint32_t kNoScope = UINT32_MAX;

enum class SymbolKind : uint8_t {
  kVariable,  // globals, locals, block members of an unnamed block, block instances
  kParameter,
  kFunction,  // one user overload (prototype and definition share it)
  kStruct,
  kBuiltinVariable,  // created on first use
  kBuiltinFunction,  // one per built-in name used; the overload of each call is in builtin_calls
};

struct Symbol {
  SymbolKind kind = SymbolKind::kVariable;
  std::string name;
  Type type{};                     // variables: declared; functions: return; structs: the struct
  std::vector<Type> parameters{};  // kFunction
  uint32_t declaration = kNoNode;  // Declarator, ParameterDeclaration, FunctionDeclaration,
                                   // StructSpecifier or InterfaceBlock; kNoNode if predeclared
  uint32_t definition = kNoNode;   // kFunction: the FunctionDeclaration with a body
  uint32_t scope = kNoScope;
  bool is_const = false;
  bool predeclared = false;              // from AnalyzeOptions (e.g. ShaderToy's uniforms)
  std::optional<int64_t> const_value{};  // const int/uint scalars with a constant initializer
  const BuiltinVariable* builtin_variable = nullptr;
};

struct Scope {
  uint32_t parent = kNoScope;  // kNoScope for the global scope (id 0)
  uint32_t node = kNoNode;     // the node that opens it (kNoNode for the global scope)
};

enum class MismatchKind : uint8_t {
  kIntForFloat,      // an int-typed expression where a float type is required
  kScalarForVector,  // a scalar initializing or assigned to a vector
};

enum class MismatchContext : uint8_t {
  kInitializer,
  kAssignment,
  kReturn,
  kCallArgument,         // user function
  kBuiltinCallArgument,  // built-in function
  kBinaryOperand,        // the other operand is a float
  kTernaryBranch,        // the other branch is a float
};

struct TypeMismatch {
  uint32_t node = kNoNode;  // the offending expression
  MismatchKind kind = MismatchKind::kIntForFloat;
  MismatchContext context = MismatchContext::kInitializer;
  Type required;
  Type actual;
};

struct AnalyzeOptions {
  int version = kEssl300;  // 100 or 300
  model::Stage stage = model::Stage::kFragment;
  // Declarations visible before the shader, e.g. ShaderToy's uniforms: a parsed header
  // (its declarations are added to the global scope; its nodes get no types) ...
  const SyntaxTree* header = nullptr;
  // ... and/or plain (name, type) pairs. Struct types here must use ids StructTable predefines.
  std::vector<std::pair<std::string, Type>> predeclared;
};

struct SemanticModel {
  int version = kEssl300;
  model::Stage stage = model::Stage::kFragment;
  StructTable structs;
  std::vector<Scope> scopes;
  std::vector<Symbol> symbols;
  // By node id of the analysed tree.
  std::vector<Type> expression_types;  // Unknown for non-expressions
  std::vector<uint32_t> references;    // IdentifierExpr/CallExpr/TypeSpecifier -> symbol used
  std::vector<uint32_t> declarations;  // declaring node -> symbol declared
  std::unordered_map<uint32_t, const BuiltinFunction*> builtin_calls;  // CallExpr -> overload
  std::vector<TypeMismatch> mismatches;  // in source order of discovery

  const Type& TypeOf(uint32_t node) const;
  // The symbol `node` refers to (or declares, for declaring nodes); kNoSymbol when none.
  uint32_t SymbolAt(uint32_t node) const;
  // Every node that refers to `symbol`, in node-id order.
  std::vector<uint32_t> UsesOf(uint32_t symbol) const;
  // Symbols named `name` (functions may have several overloads).
  std::vector<uint32_t> FindSymbols(std::string_view name) const;
  std::string Spell(const Type& type) const { return glsl::Spell(type, &structs); }
};

SemanticModel Analyze(const SyntaxTree& tree, const AnalyzeOptions& options);

// One line per expression, in source order: `line:col 'source text' : type`.
std::string DumpTypes(const SyntaxTree& tree, const SemanticModel& model,
                      const SourceManager& sources);

}  // namespace shaderport::glsl
