// The Parser class shared by parser.cpp, parse_declarations.cpp,
// parse_statements.cpp and parse_expressions.cpp. Not part of the public API.
#pragma once

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "glsl/lex/preprocessor.h"
#include "glsl/syntax/ast.h"
#include "glsl/syntax/browser_stack.h"
#include "glsl/syntax/keywords.h"
#include "glsl/syntax/parser.h"

namespace shaderport::glsl {

class Parser {
 public:
  Parser(const PreprocessResult& pp, const ParseOptions& options);
  ParseResult Run();

 private:
  void PlaceEmptyNodes();
  friend class DepthGuard;
  friend class BrowserStackGuard;

  // ---- tokens (defined below the class: inline, as the parser asks them for every
  // token several times and a call each was a tenth of the parse)
  const PpToken& Tok(uint32_t ahead = 0) const;
  uint32_t Index(uint32_t ahead = 0) const;
  std::string_view Text(uint32_t ahead = 0) const;  // continuations removed
  const WordInfo& Word(uint32_t ahead = 0) const;
  bool AtEnd() const { return Tok().kind == TokenKind::kEndOfFile; }
  bool AtPunct(Punct p, uint32_t ahead = 0) const;
  bool AtKeyword(std::string_view word, uint32_t ahead = 0) const;
  bool AtRole(WordRole role, uint32_t ahead = 0) const;
  bool AtName(uint32_t ahead = 0) const;  // an identifier that is no keyword of the version
  void Advance();
  bool Accept(Punct p);
  // Consumes `p` or reports "expected 'p' <context>" and returns false.
  bool Expect(Punct p, std::string_view context);
  Name TakeName();  // consumes the current token as a name (reports reserved words)
  Name ExpectName(std::string_view what);

  // ---- nodes and ranges (parser.cpp)
  template <class T>
  T* Start() {
    T* node = tree_.Make<T>();
    node->first_token = Index();
    return node;
  }
  // Sets the node's last token to the last consumed one and computes its range.
  template <class T>
  T* Finish(T* node) {
    FinishNode(node);
    return node;
  }
  void FinishNode(Node* node);  // inline below: it runs for every node
  void FinishNodeSlow(Node* node);
  SourceRange RangeOf(uint32_t first, uint32_t last) const;
  SourceRange TokenRange(uint32_t index) const {
    return index < token_count_ ? tokens_[index].expansion : SourceRange{};
  }

  // ---- diagnostics and recovery (parser.cpp)
  void Error(const SourceRange& range, std::string_view rule, std::string message);
  void ErrorAtToken(std::string_view rule, std::string message);
  void ErrorAfterPrevious(std::string_view rule, std::string message);
  std::string Describe(uint32_t ahead = 0) const;  // "'foo'" or "end of file"
  // Skips to just after the next `;` or before a `}` or declaration start at
  // nesting level 0. Always consumes at least one token unless at `}` or EOF.
  void RecoverToStatementEnd();
  // Skips balanced tokens without recursion, stopping before a closer that
  // would leave the current level or a `;` at level 0.
  void SkipBalanced(bool statement);
  bool TooDeep();  // reports nesting-too-deep once; true when the limit is passed
  ErrorExpr* MakeErrorExpr();

  // ---- type names and scopes (parser.cpp)
  bool IsTypeName(uint32_t ahead = 0) const;
  bool IsStructName(std::string_view name) const;
  void DeclareStruct(std::string_view name);
  void DeclareOrdinaryName(std::string_view name);  // hides a struct name in this scope
  void PushScope() { scope_marks_.push_back(scope_names_.size()); }
  void PopScope();

  // ---- declarations (parse_declarations.cpp)
  Node* ParseExternalDeclaration();
  bool StartsDeclaration() const;  // at statement level
  Node* ParseDeclaration(bool global);
  QualifierList ParseQualifiers();
  bool AtQualifierStart() const;
  bool AtReservedQualifier(uint32_t ahead = 0) const;  // `varying` in 3.00, `flat` in 1.00
  bool StartsTypeAhead() const;  // a type name (not a constructor) or `name name`
  void ParseLayout(Qualifier& qualifier);
  TypeSpecifier* ParseTypeSpecifier(const QualifierList& qualifiers);
  StructSpecifier* ParseStruct();
  void ParseArrayDimensions(std::vector<ArrayDimension>& out);
  Node* ParseFunction(const QualifierList& qualifiers, TypeSpecifier* type, uint32_t first);
  ParameterDeclaration* ParseParameter();
  Node* ParseInterfaceBlock(QualifierList qualifiers, uint32_t first);
  Node* ParseDeclaratorList(VariableDeclaration* decl);
  VariableDeclaration* ParseMemberDeclaration();
  Node* ParsePrecisionDeclaration();

  // ---- statements (parse_statements.cpp)
  Node* ParseStatement();
  CompoundStatement* ParseCompound(bool new_scope);
  Node* ParseIf();
  Node* ParseFor();
  Node* ParseWhile();
  Node* ParseDoWhile();
  Node* ParseSwitch();
  Node* ParseCaseLabel();
  Node* ParseJump();
  Node* ParseExpressionStatement();
  // Consumes ';' or reports it; skips the rest of the statement unless the
  // next token starts a new line (then the ';' was most likely just forgotten).
  bool ExpectSemicolon(std::string_view context);
  Node* ParseConditionOrDeclaration();

  // ---- expressions (parse_expressions.cpp)
  Expr* ParseExpression();  // with the comma operator
  Expr* ParseAssignment();
  Expr* ParseConditional();
  Expr* ParseBinary(int min_precedence);
  Expr* ParseUnary();
  Expr* ParsePostfix();
  Expr* ParsePrimary();
  Expr* ParseLiteral();
  Expr* ParseConstructorOrCall();
  void ParseArguments(CallExpr* call);
  bool AtConstructor() const;  // a type name starting an expression

  const PreprocessResult& pp_;
  ParseOptions options_;
  SyntaxTree tree_;
  DiagnosticList diagnostics_;
  uint32_t pos_ = 0;
  uint32_t end_index_ = 0;  // index of the kEndOfFile token
  // The tokens read: pp_.tokens, or own_tokens_ when those lack an end of file. Every
  // index up to end_index_ (where Index() stops) is inside.
  const PpToken* tokens_ = nullptr;
  const PpToken* current_ = nullptr;  // tokens_ + pos_: the token asked for most
  uint32_t token_count_ = 0;
  std::vector<PpToken> own_tokens_;
  std::vector<WordInfo> words_;
  std::vector<std::pair<std::string, bool>> scope_names_;  // (name, is struct)
  std::vector<size_t> scope_marks_;
  uint32_t depth_ = 0;  // our own recursion (DepthGuard)
  // Estimated entries of a browser's parser stack (BrowserStackGuard, browser_stack.h).
  uint32_t browser_stack_ = browser_stack::kBase;
  bool depth_reported_ = false;
  uint32_t last_error_index_ = UINT32_MAX;
  size_t error_count_ = 0;
  bool too_many_reported_ = false;
  // Set by the slow path of FinishNode, the only place a node can end up with no
  // tokens: PlaceEmptyNodes has nothing to do in a tree that never took it.
  bool took_slow_finish_ = false;
};

// pos_ never passes end_index_ (only Advance moves it), so the current token needs no
// clamp: most calls ask for it, with `ahead` a constant 0 that folds the test away.
inline uint32_t Parser::Index(uint32_t ahead) const {
  return ahead == 0 ? pos_ : std::min(pos_ + ahead, end_index_);
}

inline const PpToken& Parser::Tok(uint32_t ahead) const {
  return ahead == 0 ? *current_ : tokens_[Index(ahead)];
}

inline std::string_view Parser::Text(uint32_t ahead) const { return Tok(ahead).text; }
inline const WordInfo& Parser::Word(uint32_t ahead) const { return words_[Index(ahead)]; }

inline bool Parser::AtPunct(Punct p, uint32_t ahead) const {
  const PpToken& t = Tok(ahead);
  return t.kind == TokenKind::kPunctuator && t.punct == p;
}

inline bool Parser::AtKeyword(std::string_view word, uint32_t ahead) const {
  return Tok(ahead).kind == TokenKind::kIdentifier && Word(ahead).status == WordStatus::kKeyword &&
         Text(ahead) == word;
}

inline bool Parser::AtRole(WordRole role, uint32_t ahead) const {
  return Tok(ahead).kind == TokenKind::kIdentifier && Word(ahead).role == role &&
         Word(ahead).status == WordStatus::kKeyword;
}

inline bool Parser::AtName(uint32_t ahead) const {
  return Tok(ahead).kind == TokenKind::kIdentifier && Word(ahead).status != WordStatus::kKeyword;
}

inline void Parser::FinishNode(Node* node) {
  // The common case of RangeOf: tokens consumed, the first and last in one file (pos_
  // never passes end_index_).
  if (pos_ > node->first_token) {
    const SourceRange& first = tokens_[node->first_token].expansion;
    const SourceRange& last = tokens_[pos_ - 1].expansion;
    if (first.file == last.file) {
      node->last_token = pos_ - 1;
      node->range = {first.file, first.begin, std::max(first.begin, last.end)};
      return;
    }
  }
  FinishNodeSlow(node);
}

inline void Parser::Advance() {
  if (pos_ < end_index_) {
    ++pos_;
    ++current_;
  }
}

inline bool Parser::Accept(Punct p) {
  if (!AtPunct(p)) return false;
  Advance();
  return true;
}

// Holds `entries` on the estimated browser parser stack for as long as it lives: put
// around the parse of what a construct contains.
class BrowserStackGuard {
 public:
  BrowserStackGuard(Parser& parser, uint32_t entries) : parser_(parser), entries_(entries) {
    parser_.browser_stack_ += entries_;
  }
  ~BrowserStackGuard() { parser_.browser_stack_ -= entries_; }
  BrowserStackGuard(const BrowserStackGuard&) = delete;
  BrowserStackGuard& operator=(const BrowserStackGuard&) = delete;

 private:
  Parser& parser_;
  uint32_t entries_;
};

// Counts one level of our own recursion for as long as it lives.
class DepthGuard {
 public:
  explicit DepthGuard(Parser& parser) : parser_(parser) { ++parser_.depth_; }
  ~DepthGuard() { --parser_.depth_; }
  DepthGuard(const DepthGuard&) = delete;
  DepthGuard& operator=(const DepthGuard&) = delete;

 private:
  Parser& parser_;
};

}  // namespace shaderport::glsl
