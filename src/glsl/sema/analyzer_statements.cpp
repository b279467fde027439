#include "glsl/sema/analyzer.h"

namespace shaderport::glsl {

Analyzer::Analyzer(const SyntaxTree& tree, const AnalyzeOptions& options)
    : tree_(tree), options_(options) {
  model_.version = options.version >= kEssl300 ? kEssl300 : kEssl100;
  model_.stage = options.stage;
  model_.expression_types.assign(tree.NodeCount(), Type::Unknown());
  model_.references.assign(tree.NodeCount(), kNoSymbol);
  model_.declarations.assign(tree.NodeCount(), kNoSymbol);
}

SemanticModel Analyzer::Run() {
  PushScope(kNoNode);  // global scope, id 0
  for (const auto& [name, type] : options_.predeclared) {
    Declare({.kind = SymbolKind::kVariable, .name = name, .type = type, .predeclared = true});
  }
  if (options_.header != nullptr && options_.header->Root() != nullptr) {
    recording_ = false;
    header_types_.assign(options_.header->NodeCount(), Type::Unknown());
    types_ = &header_types_;
    for (const Node* node : options_.header->Root()->declarations) DeclareExternal(*node);
    recording_ = true;
  }
  types_ = &model_.expression_types;
  if (tree_.Root() != nullptr) {
    for (const Node* node : tree_.Root()->declarations) DeclareExternal(*node);
  }
  return std::move(model_);
}

void Analyzer::PushScope(uint32_t node) {
  model_.scopes.push_back({current_scope_, recording_ ? node : kNoNode});
  current_scope_ = static_cast<uint32_t>(model_.scopes.size() - 1);
  scope_marks_.push_back(scope_symbols_.size());
}

void Analyzer::PopScope() {
  current_scope_ = model_.scopes[current_scope_].parent;
  // The scope's own symbols are the last of their names' lists: drop them, newest first.
  const size_t mark = scope_marks_.back();
  scope_marks_.pop_back();
  for (size_t i = scope_symbols_.size(); i-- > mark;) scope_symbols_[i]->pop_back();
  scope_symbols_.resize(mark);
}

uint32_t Analyzer::Declare(Symbol symbol) {
  symbol.scope = current_scope_;
  if (!recording_) {
    symbol.predeclared = true;
    symbol.declaration = kNoNode;
    symbol.definition = kNoNode;
  }
  uint32_t id = static_cast<uint32_t>(model_.symbols.size());
  if (symbol.declaration != kNoNode) model_.declarations[symbol.declaration] = id;
  std::vector<uint32_t>& same_name = visible_[symbol.name];
  same_name.push_back(id);
  scope_symbols_.push_back(&same_name);
  model_.symbols.push_back(std::move(symbol));
  return id;
}

uint32_t Analyzer::Lookup(const std::string& name) const {
  auto it = visible_.find(name);
  if (it == visible_.end() || it->second.empty()) return kNoSymbol;
  return it->second.back();
}

std::vector<uint32_t> Analyzer::LookupFunctions(const std::string& name) const {
  // A nearer variable or struct of that name hides the functions (GLSL scoping): the
  // answer is every symbol of that name in the innermost scope that has one.
  auto it = visible_.find(name);
  if (it == visible_.end() || it->second.empty()) return {};
  const std::vector<uint32_t>& ids = it->second;
  const Symbol& nearest = model_.symbols[ids.back()];
  if (nearest.kind != SymbolKind::kFunction) return {};
  size_t first = ids.size() - 1;
  while (first > 0 && model_.symbols[ids[first - 1]].scope == nearest.scope) --first;
  return std::vector<uint32_t>(ids.begin() + static_cast<std::ptrdiff_t>(first), ids.end());
}

void Analyzer::Refer(uint32_t node, uint32_t symbol) {
  if (recording_ && node < model_.references.size()) model_.references[node] = symbol;
}

void Analyzer::DeclareExternal(const Node& node) {
  switch (node.kind) {
    case NodeKind::kFunctionDeclaration:
      return FunctionDeclarationNode(*node.As<FunctionDeclaration>());
    default:
      return Statement(&node);
  }
}

int32_t Analyzer::ArraySize(const std::vector<ArrayDimension>& dims) {
  if (dims.empty()) return Type::kNotArray;
  // ESSL 1.00 and 3.00 have one dimension; extra ones are a syntax-level error.
  const ArrayDimension& dim = dims.front();
  if (dim.size == nullptr) return Type::kUnsizedArray;
  TypeExpression(dim.size);
  std::optional<int64_t> value = ConstantInt(dim.size);
  if (!value || *value <= 0 || *value > INT32_MAX) return Type::kUnsizedArray;
  return static_cast<int32_t>(*value);
}

uint32_t Analyzer::DeclareStruct(const StructSpecifier& spec) {
  StructInfo info;
  info.name = spec.name.text;
  info.declaration = recording_ ? spec.id : kNoNode;
  for (const VariableDeclaration* field : spec.fields) {
    if (field == nullptr) continue;
    Type base = ResolveTypeSpecifier(field->type);
    for (const Declarator* d : field->declarators) {
      if (d == nullptr) continue;
      Type t = base;
      if (int32_t size = ArraySize(d->array); size != Type::kNotArray) t = t.ArrayOf(size);
      info.fields.push_back({d->name.text, t});
    }
  }
  uint32_t id = model_.structs.Add(std::move(info));
  if (!spec.name.Empty()) {
    Declare({.kind = SymbolKind::kStruct,
             .name = spec.name.text,
             .type = Type::Struct(id),
             .declaration = spec.id});
  }
  return id;
}

Type Analyzer::ResolveTypeSpecifier(const TypeSpecifier* spec) {
  if (spec == nullptr) return Type::Unknown();
  Type type = Type::Unknown();
  if (spec->struct_def != nullptr) {
    type = Type::Struct(DeclareStruct(*spec->struct_def));
  } else if (std::optional<Type> builtin = BuiltinTypeByName(spec->name.text)) {
    type = *builtin;
  } else {
    uint32_t symbol = Lookup(spec->name.text);
    if (symbol != kNoSymbol && model_.symbols[symbol].kind == SymbolKind::kStruct) {
      type = model_.symbols[symbol].type;
      Refer(spec->id, symbol);
    }
  }
  if (int32_t size = ArraySize(spec->array); size != Type::kNotArray) type = type.ArrayOf(size);
  return type;
}

void Analyzer::VariableDeclarationNode(const VariableDeclaration& decl) {
  Type base = ResolveTypeSpecifier(decl.type);
  bool is_const = decl.qualifiers.Has(QualifierKind::kConst);
  for (const Declarator* d : decl.declarators) {
    if (d == nullptr) continue;
    Type type = base;
    if (int32_t size = ArraySize(d->array); size != Type::kNotArray) type = type.ArrayOf(size);
    std::optional<int64_t> value;
    if (d->initializer != nullptr) {
      Type init = TypeExpression(d->initializer);
      // `float a[] = float[](...)` takes its size from the initializer.
      if (type.array_size == Type::kUnsizedArray && init.IsArray() &&
          init.Element() == type.Element()) {
        type = init;
      }
      CheckRequired(d->initializer, type, MismatchContext::kInitializer);
      if (is_const && type.IsIntegral() && type.IsScalar()) value = ConstantInt(d->initializer);
    }
    Declare({.kind = SymbolKind::kVariable,
             .name = d->name.text,
             .type = type,
             .declaration = d->id,
             .is_const = is_const,
             .const_value = value});
  }
}

void Analyzer::InterfaceBlockNode(const InterfaceBlock& block) {
  StructInfo info;
  info.name = block.block_name.text;
  info.declaration = recording_ ? block.id : kNoNode;
  std::vector<std::pair<const Declarator*, Type>> members;
  for (const VariableDeclaration* member : block.members) {
    if (member == nullptr) continue;
    Type base = ResolveTypeSpecifier(member->type);
    for (const Declarator* d : member->declarators) {
      if (d == nullptr) continue;
      Type t = base;
      if (int32_t size = ArraySize(d->array); size != Type::kNotArray) t = t.ArrayOf(size);
      info.fields.push_back({d->name.text, t});
      members.emplace_back(d, t);
    }
  }
  uint32_t id = model_.structs.Add(std::move(info));
  if (block.instance_name.Empty()) {
    for (const auto& [d, t] : members) {
      Declare(
          {.kind = SymbolKind::kVariable, .name = d->name.text, .type = t, .declaration = d->id});
    }
    return;
  }
  Type type = Type::Struct(id);
  if (int32_t size = ArraySize(block.instance_array); size != Type::kNotArray) {
    type = type.ArrayOf(size);
  }
  Declare({.kind = SymbolKind::kVariable,
           .name = block.instance_name.text,
           .type = type,
           .declaration = block.id});
}

void Analyzer::FunctionDeclarationNode(const FunctionDeclaration& fn) {
  Type return_type = ResolveTypeSpecifier(fn.return_type);
  std::vector<Type> params;
  for (const ParameterDeclaration* p : fn.parameters) {
    if (p == nullptr) continue;
    Type t = ResolveTypeSpecifier(p->type);
    if (int32_t size = ArraySize(p->array); size != Type::kNotArray) t = t.ArrayOf(size);
    params.push_back(t);
  }
  // A prototype and its definition share one symbol.
  uint32_t symbol = kNoSymbol;
  for (uint32_t candidate : LookupFunctions(fn.name.text)) {
    if (model_.symbols[candidate].parameters == params) symbol = candidate;
  }
  if (symbol == kNoSymbol) {
    symbol = Declare({.kind = SymbolKind::kFunction,
                      .name = fn.name.text,
                      .type = return_type,
                      .parameters = params,
                      .declaration = fn.id});
  } else if (recording_) {
    model_.declarations[fn.id] = symbol;
  }
  if (fn.body == nullptr) return;
  if (recording_) model_.symbols[symbol].definition = fn.id;
  PushScope(fn.id);
  size_t i = 0;
  for (const ParameterDeclaration* p : fn.parameters) {
    if (p == nullptr) continue;
    if (!p->name.Empty()) {
      Declare({.kind = SymbolKind::kParameter,
               .name = p->name.text,
               .type = params[i],
               .declaration = p->id,
               .is_const = p->qualifiers.Has(QualifierKind::kConst)});
    }
    ++i;
  }
  current_return_ = return_type;
  // The body shares the parameters' scope, as GLSL specifies.
  for (const Node* s : fn.body->statements) Statement(s);
  current_return_ = Type::Unknown();
  PopScope();
}

void Analyzer::Statement(const Node* node) {
  if (node == nullptr) return;
  if (node->IsExpr()) {
    TypeExpression(node->As<Expr>());
    return;
  }
  switch (node->kind) {
    case NodeKind::kVariableDeclaration:
      return VariableDeclarationNode(*node->As<VariableDeclaration>());
    case NodeKind::kInterfaceBlock:
      return InterfaceBlockNode(*node->As<InterfaceBlock>());
    case NodeKind::kFunctionDeclaration:
      return FunctionDeclarationNode(*node->As<FunctionDeclaration>());
    case NodeKind::kCompoundStatement:
      PushScope(node->id);
      for (const Node* s : node->As<CompoundStatement>()->statements) Statement(s);
      return PopScope();
    case NodeKind::kExpressionStatement:
      TypeExpression(node->As<ExpressionStatement>()->expression);
      return;
    case NodeKind::kIfStatement: {
      const auto* n = node->As<IfStatement>();
      TypeExpression(n->condition);
      Statement(n->then_branch);
      return Statement(n->else_branch);
    }
    case NodeKind::kForStatement: {
      const auto* n = node->As<ForStatement>();
      PushScope(node->id);
      Statement(n->init);
      Statement(n->condition);
      TypeExpression(n->increment);
      Statement(n->body);
      return PopScope();
    }
    case NodeKind::kWhileStatement: {
      const auto* n = node->As<WhileStatement>();
      PushScope(node->id);
      Statement(n->condition);
      Statement(n->body);
      return PopScope();
    }
    case NodeKind::kDoWhileStatement: {
      const auto* n = node->As<DoWhileStatement>();
      Statement(n->body);
      TypeExpression(n->condition);
      return;
    }
    case NodeKind::kSwitchStatement: {
      const auto* n = node->As<SwitchStatement>();
      TypeExpression(n->selector);
      return Statement(n->body);
    }
    case NodeKind::kCaseLabel:
      TypeExpression(node->As<CaseLabel>()->value);
      return;
    case NodeKind::kReturnStatement: {
      const auto* n = node->As<ReturnStatement>();
      if (n->value == nullptr) return;
      TypeExpression(n->value);
      CheckRequired(n->value, current_return_, MismatchContext::kReturn);
      return;
    }
    default:
      return;  // precision and qualifier declarations, jumps, empty and error statements
  }
}

}  // namespace shaderport::glsl
