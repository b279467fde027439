// Internal to sema: the pass that builds a SemanticModel. Declarations and
// statements are in analyzer_statements.cpp, expressions in analyzer_expressions.cpp.
#pragma once

#include <deque>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "glsl/sema/semantic_model.h"

namespace shaderport::glsl {

class Analyzer {
 public:
  Analyzer(const SyntaxTree& tree, const AnalyzeOptions& options);
  SemanticModel Run();

 private:
  // Scopes and symbols.
  void PushScope(uint32_t node);
  void PopScope();
  uint32_t Declare(Symbol symbol);
  uint32_t Lookup(const std::string& name) const;
  std::vector<uint32_t> LookupFunctions(const std::string& name) const;
  void Refer(uint32_t node, uint32_t symbol);

  // Declarations and statements (analyzer_statements.cpp).
  void DeclareExternal(const Node& node);
  void Statement(const Node* node);
  void VariableDeclarationNode(const VariableDeclaration& decl);
  void FunctionDeclarationNode(const FunctionDeclaration& fn);
  void InterfaceBlockNode(const InterfaceBlock& block);
  Type ResolveTypeSpecifier(const TypeSpecifier* spec);
  uint32_t DeclareStruct(const StructSpecifier& spec);
  int32_t ArraySize(const std::vector<ArrayDimension>& dims);

  // Expressions (analyzer_expressions.cpp). Typed bottom-up with an explicit stack, so
  // that long operator chains cannot exhaust the native stack.
  Type TypeExpression(const Expr* expr);
  Type ComputeType(const Expr& expr);
  Type CallType(const CallExpr& call);
  Type FunctionCallType(const CallExpr& call, const std::vector<Type>& args);
  Type MemberType(const MemberExpr& member);
  Type BinaryType(const BinaryExpr& binary);
  Type AssignmentType(const AssignmentExpr& assignment);
  Type ConditionalType(const ConditionalExpr& conditional);
  // Records mismatches for `value` where `required` is needed; returns true if it found one.
  bool CheckRequired(const Expr* value, const Type& required, MismatchContext context);
  void AddMismatch(const Expr* node, MismatchKind kind, MismatchContext context,
                   const Type& required, const Type& actual);
  std::optional<int64_t> ConstantInt(const Expr* expr, int depth = 0) const;
  const Type& TypeAt(const Expr* expr) const;

  const SyntaxTree& tree_;
  AnalyzeOptions options_;
  SemanticModel model_;
  bool recording_ = true;               // false while reading the predeclared header tree
  std::vector<Type>* types_ = nullptr;  // expression types of the tree being read
  std::vector<Type> header_types_;
  uint32_t current_scope_ = kNoScope;
  // One table of the names in scope, each with its symbols, outermost first (inner
  // scopes declare after outer ones): a lookup is one hash, not one per open scope.
  std::unordered_map<std::string, std::vector<uint32_t>> visible_;
  // For each symbol declared in the open scopes, in order, its name's list in visible_
  // (map nodes never move), so that closing a scope hashes no name again.
  std::vector<std::vector<uint32_t>*> scope_symbols_;
  std::vector<size_t> scope_marks_;  // scope_symbols_.size() when each scope opened
  std::unordered_map<std::string, uint32_t> builtin_symbols_;  // built-in variables by name
  // Built-in functions by their overload list (one per name): no key string to build.
  std::unordered_map<const BuiltinFunction* const*, uint32_t> builtin_function_symbols_;
  std::vector<Type> call_arguments_;  // CallType's argument types, kept between calls
  Type current_return_ = Type::Unknown();
  // Work lists of TypeExpression, kept between calls (it runs for every expression
  // statement and initializer, and two fresh vectors a call were a heap allocation
  // each); one per nesting level, as typing a constructor's array size re-enters it.
  struct TypingScratch {
    std::vector<std::pair<const Expr*, bool>> stack;
    std::vector<const Expr*> operands;
  };
  std::deque<TypingScratch> typing_scratch_;
  size_t typing_depth_ = 0;
};

}  // namespace shaderport::glsl
