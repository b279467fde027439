// Declarations: variables, structs, functions, interface blocks, precision.
#include "glsl/syntax/parser_internal.h"

namespace shaderport::glsl {
namespace {

struct QualifierWord {
  std::string_view word;
  QualifierKind kind;
};

constexpr QualifierWord kQualifierWords[] = {
    {"const", QualifierKind::kConst},
    {"in", QualifierKind::kIn},
    {"out", QualifierKind::kOut},
    {"inout", QualifierKind::kInOut},
    {"uniform", QualifierKind::kUniform},
    {"attribute", QualifierKind::kAttribute},
    {"varying", QualifierKind::kVarying},
    {"centroid", QualifierKind::kCentroid},
    {"flat", QualifierKind::kFlat},
    {"smooth", QualifierKind::kSmooth},
    {"invariant", QualifierKind::kInvariant},
    {"layout", QualifierKind::kLayout},
};

QualifierKind QualifierKindOf(std::string_view word) {
  for (const auto& q : kQualifierWords) {
    if (q.word == word) return q.kind;
  }
  return QualifierKind::kConst;
}

Precision PrecisionOf(std::string_view word) {
  if (word == "lowp") return Precision::kLow;
  if (word == "mediump") return Precision::kMedium;
  return Precision::kHigh;
}

}  // namespace

bool Parser::AtReservedQualifier(uint32_t ahead) const {
  if (Tok(ahead).kind != TokenKind::kIdentifier || Word(ahead).status != WordStatus::kReserved) {
    return false;
  }
  std::string_view text = Text(ahead);
  return text == "attribute" || text == "varying" || text == "flat";
}

bool Parser::AtQualifierStart() const {
  return AtRole(WordRole::kQualifier) || AtRole(WordRole::kPrecisionQualifier) ||
         (AtReservedQualifier() && Tok(1).kind == TokenKind::kIdentifier);
}

bool Parser::StartsTypeAhead() const {
  if (AtRole(WordRole::kStruct)) return true;
  if (IsTypeName()) {
    if (AtPunct(Punct::kLeftParen, 1) || AtPunct(Punct::kDot, 1)) return false;
    if (!AtPunct(Punct::kLeftBracket, 1)) return true;
    // `float[2] a` declares, `float[2](...)` constructs: look past the brackets.
    uint32_t level = 0;
    for (uint32_t k = 1;; ++k) {
      const PpToken& t = Tok(k);
      if (t.kind == TokenKind::kEndOfFile) return true;
      if (t.kind != TokenKind::kPunctuator) continue;
      if (t.punct == Punct::kLeftBracket) ++level;
      if (t.punct == Punct::kRightBracket && --level == 0) {
        if (!AtPunct(Punct::kLeftBracket, k + 1)) return !AtPunct(Punct::kLeftParen, k + 1);
      }
      if (t.punct == Punct::kSemicolon || t.punct == Punct::kLeftBrace) return true;
    }
  }
  // `Foo bar` with Foo unknown: a declaration of an unknown type (sema reports it).
  return AtName() && AtName(1);
}

bool Parser::StartsDeclaration() const {
  return AtQualifierStart() || AtRole(WordRole::kPrecision) || StartsTypeAhead();
}

Node* Parser::ParseExternalDeclaration() {
  if (AtPunct(Punct::kSemicolon)) {
    // Not allowed by ESSL at global scope, but browsers accept it (`void f() {};`):
    // kept as an EmptyStatement for rules to flag.
    auto* empty = Start<EmptyStatement>();
    Advance();
    return Finish(empty);
  }
  if (StartsDeclaration()) return ParseDeclaration(true);
  auto* error = Start<ErrorStatement>();
  if (Tok().kind == TokenKind::kInvalid) {  // the lexer already reported the byte
    Advance();
    return Finish(error);
  }
  ErrorAtToken("syntax/unexpected-token", "expected a declaration, found " + Describe());
  uint32_t before = pos_;
  RecoverToStatementEnd();
  if (pos_ == before) Advance();
  return Finish(error);
}

QualifierList Parser::ParseQualifiers() {
  QualifierList list;
  while (AtQualifierStart()) {
    Qualifier q;
    q.range = Tok().expansion;
    if (AtRole(WordRole::kPrecisionQualifier)) {
      q.kind = QualifierKind::kPrecision;
      q.precision = PrecisionOf(Text());
      Advance();
    } else if (AtReservedQualifier()) {
      q.kind = QualifierKindOf(Text());
      TakeName();  // reports syntax/reserved-word and goes on as if it were allowed
    } else {
      q.kind = QualifierKindOf(Text());
      uint32_t first = Index();
      Advance();
      if (q.kind == QualifierKind::kLayout) {
        ParseLayout(q);
        q.range = RangeOf(first, pos_ - 1);
      }
    }
    list.items.push_back(std::move(q));
  }
  return list;
}

void Parser::ParseLayout(Qualifier& qualifier) {
  if (!Expect(Punct::kLeftParen, "after 'layout'")) return;
  while (!AtPunct(Punct::kRightParen) && !AtEnd()) {
    LayoutId id;
    id.name = ExpectName("a layout qualifier name");
    if (id.name.Empty()) break;
    if (Accept(Punct::kEqual)) id.value = ParseConditional();
    qualifier.layout_ids.push_back(std::move(id));
    if (!Accept(Punct::kComma)) break;
  }
  if (!Expect(Punct::kRightParen, "to close 'layout('")) {
    SkipBalanced(false);
    Accept(Punct::kRightParen);
  }
}

void Parser::ParseArrayDimensions(std::vector<ArrayDimension>& out) {
  while (AtPunct(Punct::kLeftBracket)) {
    ArrayDimension dim;
    uint32_t first = Index();
    Advance();
    if (!AtPunct(Punct::kRightBracket)) {
      BrowserStackGuard stack(*this, browser_stack::kArraySize);
      dim.size = ParseConditional();
    }
    if (!Expect(Punct::kRightBracket, "to close the array size")) {
      SkipBalanced(false);
      Accept(Punct::kRightBracket);
    }
    dim.range = RangeOf(first, pos_ - 1);
    out.push_back(dim);
  }
}

TypeSpecifier* Parser::ParseTypeSpecifier(const QualifierList& qualifiers) {
  auto* type = Start<TypeSpecifier>();
  for (const auto& q : qualifiers.items) {
    if (q.kind == QualifierKind::kPrecision) type->precision = q.precision;
  }
  if (AtRole(WordRole::kStruct)) {
    type->struct_def = ParseStruct();
    type->name = type->struct_def->name;
    type->name_kind = TypeNameKind::kStruct;
  } else if (IsTypeName()) {
    type->name_kind =
        Word().role == WordRole::kType ? TypeNameKind::kBuiltin : TypeNameKind::kStruct;
    type->name = {std::string(Text()), Tok().expansion};
    Advance();
  } else if (AtName()) {
    type->name_kind = TypeNameKind::kUnknown;
    type->name = TakeName();
  } else {
    type->name_kind = TypeNameKind::kUnknown;
    ErrorAtToken("syntax/unexpected-token", "expected a type, found " + Describe());
    return Finish(type);
  }
  ParseArrayDimensions(type->array);
  return Finish(type);
}

StructSpecifier* Parser::ParseStruct() {
  DepthGuard guard(*this);
  auto* node = Start<StructSpecifier>();
  Advance();  // `struct`
  if (AtName()) node->name = TakeName();
  if (TooDeep()) {
    SkipBalanced(true);
    return Finish(node);
  }
  if (!Expect(Punct::kLeftBrace, "in struct definition")) return Finish(node);
  BrowserStackGuard stack(*this, browser_stack::kStructBody);
  while (!AtPunct(Punct::kRightBrace) && !AtEnd()) {
    uint32_t before = pos_;
    node->fields.push_back(ParseMemberDeclaration());
    if (pos_ == before) Advance();
  }
  Expect(Punct::kRightBrace, "to end the struct");
  DeclareStruct(node->name.text);
  return Finish(node);
}

VariableDeclaration* Parser::ParseMemberDeclaration() {
  auto* decl = Start<VariableDeclaration>();
  decl->qualifiers = ParseQualifiers();
  decl->type = ParseTypeSpecifier(decl->qualifiers);
  if (decl->type->name.Empty() && decl->type->struct_def == nullptr) {
    RecoverToStatementEnd();
    return Finish(decl);
  }
  ParseDeclaratorList(decl);
  return decl;
}

Node* Parser::ParsePrecisionDeclaration() {
  auto* node = Start<PrecisionDeclaration>();
  Advance();  // `precision`
  if (AtRole(WordRole::kPrecisionQualifier)) {
    node->precision = PrecisionOf(Text());
    Advance();
  } else {
    ErrorAtToken("syntax/unexpected-token",
                 "expected 'lowp', 'mediump' or 'highp', found " + Describe());
  }
  node->type = ParseTypeSpecifier({});
  ExpectSemicolon("after precision statement");
  return Finish(node);
}

Node* Parser::ParseDeclaration(bool global) {
  if (AtRole(WordRole::kPrecision)) return ParsePrecisionDeclaration();
  uint32_t first = Index();
  QualifierList qualifiers = ParseQualifiers();
  bool invariant_names = qualifiers.Has(QualifierKind::kInvariant) && AtName() && !IsTypeName() &&
                         (AtPunct(Punct::kComma, 1) || AtPunct(Punct::kSemicolon, 1));
  if (!qualifiers.Empty() && (AtPunct(Punct::kSemicolon) || invariant_names)) {
    auto* node = tree_.Make<QualifierDeclaration>();
    node->first_token = first;
    node->qualifiers = std::move(qualifiers);
    while (invariant_names && AtName()) {
      node->names.push_back(TakeName());
      if (!Accept(Punct::kComma)) break;
    }
    ExpectSemicolon("after declaration");
    return Finish(node);
  }
  if (!qualifiers.Empty() && AtName() && !IsTypeName() && AtPunct(Punct::kLeftBrace, 1)) {
    return ParseInterfaceBlock(std::move(qualifiers), first);
  }
  TypeSpecifier* type = ParseTypeSpecifier(qualifiers);
  if (AtName() && AtPunct(Punct::kLeftParen, 1)) return ParseFunction(qualifiers, type, first);
  (void)global;
  auto* decl = tree_.Make<VariableDeclaration>();
  decl->first_token = first;
  decl->qualifiers = std::move(qualifiers);
  decl->type = type;
  if (type->name.Empty() && type->struct_def == nullptr) {
    RecoverToStatementEnd();
    return Finish(decl);
  }
  return ParseDeclaratorList(decl);
}

Node* Parser::ParseDeclaratorList(VariableDeclaration* decl) {
  if (!AtPunct(Punct::kSemicolon)) {
    while (true) {
      if (!AtName()) {
        ExpectName("a name in the declaration");
        RecoverToStatementEnd();
        return Finish(decl);
      }
      auto* d = Start<Declarator>();
      d->name = TakeName();
      DeclareOrdinaryName(d->name.text);
      ParseArrayDimensions(d->array);
      if (Accept(Punct::kEqual)) {
        BrowserStackGuard stack(*this, browser_stack::kInitializer);
        d->initializer = ParseAssignment();
      }
      decl->declarators.push_back(Finish(d));
      if (!Accept(Punct::kComma)) break;
    }
  }
  ExpectSemicolon("after declaration");
  return Finish(decl);
}

Node* Parser::ParseInterfaceBlock(QualifierList qualifiers, uint32_t first) {
  auto* block = tree_.Make<InterfaceBlock>();
  block->first_token = first;
  block->qualifiers = std::move(qualifiers);
  block->block_name = TakeName();
  Advance();  // `{`
  while (!AtPunct(Punct::kRightBrace) && !AtEnd()) {
    uint32_t before = pos_;
    block->members.push_back(ParseMemberDeclaration());
    if (pos_ == before) Advance();
  }
  Expect(Punct::kRightBrace, "to end the interface block");
  if (AtName()) {
    block->instance_name = TakeName();
    ParseArrayDimensions(block->instance_array);
  }
  ExpectSemicolon("after interface block");
  return Finish(block);
}

Node* Parser::ParseFunction(const QualifierList& qualifiers, TypeSpecifier* type, uint32_t first) {
  auto* fn = tree_.Make<FunctionDeclaration>();
  fn->first_token = first;
  fn->qualifiers = qualifiers;
  fn->return_type = type;
  fn->name = TakeName();
  Advance();  // `(`
  PushScope();
  if (AtKeyword("void") && AtPunct(Punct::kRightParen, 1)) {
    fn->void_parameter = true;
    Advance();
  } else {
    while (!AtPunct(Punct::kRightParen) && !AtEnd()) {
      uint32_t before = pos_;
      fn->parameters.push_back(ParseParameter());
      if (pos_ == before || !Accept(Punct::kComma)) break;
    }
  }
  if (!Expect(Punct::kRightParen, "to close the parameter list")) {
    SkipBalanced(false);
    Accept(Punct::kRightParen);
  }
  if (AtPunct(Punct::kLeftBrace)) {
    BrowserStackGuard stack(*this, browser_stack::kFunctionBody);
    fn->body = ParseCompound(false);
  } else {
    ExpectSemicolon("after function prototype");
  }
  PopScope();
  return Finish(fn);
}

ParameterDeclaration* Parser::ParseParameter() {
  auto* param = Start<ParameterDeclaration>();
  param->qualifiers = ParseQualifiers();
  param->type = ParseTypeSpecifier(param->qualifiers);
  if (AtName()) {
    param->name = TakeName();
    DeclareOrdinaryName(param->name.text);
    ParseArrayDimensions(param->array);
  }
  return Finish(param);
}

}  // namespace shaderport::glsl
