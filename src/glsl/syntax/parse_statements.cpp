// Statements: compound, selection, iteration, switch and jumps.
#include "glsl/syntax/parser_internal.h"

namespace shaderport::glsl {

bool Parser::ExpectSemicolon(std::string_view context) {
  if (Accept(Punct::kSemicolon)) return true;
  Expect(Punct::kSemicolon, context);
  if (!Tok().at_line_start && !AtPunct(Punct::kRightBrace)) RecoverToStatementEnd();
  return false;
}

Node* Parser::ParseStatement() {
  DepthGuard guard(*this);
  if (TooDeep()) {
    auto* error = Start<ErrorStatement>();
    SkipBalanced(true);
    return Finish(error);
  }
  if (AtPunct(Punct::kLeftBrace)) {
    BrowserStackGuard stack(*this, browser_stack::kBlock);
    return ParseCompound(true);
  }
  if (AtPunct(Punct::kSemicolon)) {
    auto* empty = Start<EmptyStatement>();
    Advance();
    return Finish(empty);
  }
  if (AtRole(WordRole::kControl)) {
    std::string_view word = Text();
    if (word == "if") return ParseIf();
    if (word == "for") return ParseFor();
    if (word == "while") return ParseWhile();
    if (word == "do") return ParseDoWhile();
    if (word == "switch") return ParseSwitch();
    if (word == "case" || word == "default") return ParseCaseLabel();
    if (word != "else") return ParseJump();
    auto* error = Start<ErrorStatement>();
    ErrorAtToken("syntax/unexpected-token", "'else' without a matching 'if'");
    Advance();
    return Finish(error);
  }
  if (StartsDeclaration()) return ParseDeclaration(false);
  return ParseExpressionStatement();
}

Node* Parser::ParseExpressionStatement() {
  auto* statement = Start<ExpressionStatement>();
  statement->expression = ParseExpression();
  if (statement->expression->kind == NodeKind::kErrorExpr && !statement->expression->HasTokens()) {
    // Nothing could start an expression here: skip instead of reporting a cascade.
    RecoverToStatementEnd();
    return Finish(statement);
  }
  ExpectSemicolon("after expression");
  return Finish(statement);
}

CompoundStatement* Parser::ParseCompound(bool new_scope) {
  auto* block = Start<CompoundStatement>();
  Advance();  // `{`
  if (new_scope) PushScope();
  while (!AtPunct(Punct::kRightBrace) && !AtEnd()) {
    uint32_t before = pos_;
    block->statements.push_back(ParseStatement());
    if (pos_ == before) {
      ErrorAtToken("syntax/unexpected-token", "unexpected " + Describe());
      Advance();
    }
  }
  Expect(Punct::kRightBrace, "to end the block");
  if (new_scope) PopScope();
  return Finish(block);
}

Node* Parser::ParseIf() {
  auto* node = Start<IfStatement>();
  Advance();
  Expect(Punct::kLeftParen, "after 'if'");
  {
    BrowserStackGuard stack(*this, browser_stack::kCondition);
    node->condition = ParseExpression();
  }
  if (!Expect(Punct::kRightParen, "after the 'if' condition")) {
    SkipBalanced(false);
    Accept(Punct::kRightParen);
  }
  {
    BrowserStackGuard stack(*this, browser_stack::kThenBranch);
    node->then_branch = ParseStatement();
  }
  if (AtKeyword("else")) {
    Advance();
    BrowserStackGuard stack(*this, browser_stack::kElseBranch);
    node->else_branch = ParseStatement();
  }
  return Finish(node);
}

Node* Parser::ParseConditionOrDeclaration() {
  if (!StartsDeclaration() || AtRole(WordRole::kPrecision)) return ParseExpression();
  // `bool b = f()` as a loop condition: one declarator with an initializer, no ';'.
  auto* decl = Start<VariableDeclaration>();
  decl->qualifiers = ParseQualifiers();
  decl->type = ParseTypeSpecifier(decl->qualifiers);
  auto* d = Start<Declarator>();
  d->name = ExpectName("a name in the condition");
  DeclareOrdinaryName(d->name.text);
  if (Expect(Punct::kEqual, "in a condition declaration")) {
    BrowserStackGuard stack(*this, browser_stack::kInitializer);
    d->initializer = ParseAssignment();
  }
  decl->declarators.push_back(Finish(d));
  return Finish(decl);
}

Node* Parser::ParseFor() {
  auto* node = Start<ForStatement>();
  Advance();
  Expect(Punct::kLeftParen, "after 'for'");
  PushScope();
  BrowserStackGuard header(*this, browser_stack::kLoopHeader);
  if (AtPunct(Punct::kSemicolon)) {
    auto* empty = Start<EmptyStatement>();
    Advance();
    node->init = Finish(empty);
  } else if (StartsDeclaration()) {
    node->init = ParseDeclaration(false);
  } else {
    node->init = ParseExpressionStatement();
  }
  if (!AtPunct(Punct::kSemicolon)) node->condition = ParseConditionOrDeclaration();
  Expect(Punct::kSemicolon, "after the 'for' condition");
  if (!AtPunct(Punct::kRightParen)) node->increment = ParseExpression();
  if (!Expect(Punct::kRightParen, "to close the 'for' header")) {
    SkipBalanced(false);
    Accept(Punct::kRightParen);
  }
  {
    BrowserStackGuard body(*this, browser_stack::kLoopBody - browser_stack::kLoopHeader);
    node->body = ParseStatement();
  }
  PopScope();
  return Finish(node);
}

Node* Parser::ParseWhile() {
  auto* node = Start<WhileStatement>();
  Advance();
  Expect(Punct::kLeftParen, "after 'while'");
  PushScope();
  {
    BrowserStackGuard stack(*this, browser_stack::kCondition);
    node->condition = ParseConditionOrDeclaration();
  }
  if (!Expect(Punct::kRightParen, "after the 'while' condition")) {
    SkipBalanced(false);
    Accept(Punct::kRightParen);
  }
  {
    BrowserStackGuard stack(*this, browser_stack::kLoopBody);
    node->body = ParseStatement();
  }
  PopScope();
  return Finish(node);
}

Node* Parser::ParseDoWhile() {
  auto* node = Start<DoWhileStatement>();
  Advance();
  {
    BrowserStackGuard stack(*this, browser_stack::kDoBody);
    node->body = ParseStatement();
  }
  if (AtKeyword("while")) {
    Advance();
  } else {
    ErrorAtToken("syntax/expected-token", "expected 'while' in do/while loop, found " + Describe());
  }
  Expect(Punct::kLeftParen, "after 'while'");
  {
    BrowserStackGuard stack(*this, browser_stack::kCondition);
    node->condition = ParseExpression();
  }
  if (!Expect(Punct::kRightParen, "after the 'while' condition")) {
    SkipBalanced(false);
    Accept(Punct::kRightParen);
  }
  ExpectSemicolon("after do/while statement");
  return Finish(node);
}

Node* Parser::ParseSwitch() {
  auto* node = Start<SwitchStatement>();
  Advance();
  Expect(Punct::kLeftParen, "after 'switch'");
  {
    BrowserStackGuard stack(*this, browser_stack::kCondition);
    node->selector = ParseExpression();
  }
  if (!Expect(Punct::kRightParen, "after the 'switch' selector")) {
    SkipBalanced(false);
    Accept(Punct::kRightParen);
  }
  if (AtPunct(Punct::kLeftBrace)) {
    BrowserStackGuard stack(*this, browser_stack::kSwitchBody);
    node->body = ParseCompound(true);
  } else {
    ErrorAtToken("syntax/expected-token", "expected '{' after 'switch', found " + Describe());
  }
  return Finish(node);
}

Node* Parser::ParseCaseLabel() {
  auto* node = Start<CaseLabel>();
  bool is_case = Text() == "case";
  Advance();
  if (is_case) {
    BrowserStackGuard stack(*this, browser_stack::kCondition);
    node->value = ParseExpression();
  }
  Expect(Punct::kColon, is_case ? "after 'case' value" : "after 'default'");
  return Finish(node);
}

Node* Parser::ParseJump() {
  std::string_view word = Text();
  Node* node = nullptr;
  if (word == "return") {
    auto* ret = Start<ReturnStatement>();
    Advance();
    if (!AtPunct(Punct::kSemicolon)) {
      BrowserStackGuard stack(*this, browser_stack::kReturnValue);
      ret->value = ParseExpression();
    }
    ExpectSemicolon("after return statement");
    return Finish(ret);
  }
  if (word == "break") {
    node = Start<BreakStatement>();
  } else if (word == "continue") {
    node = Start<ContinueStatement>();
  } else {
    node = Start<DiscardStatement>();
  }
  std::string context = "after '" + std::string(word) + "'";
  Advance();
  ExpectSemicolon(context);
  FinishNode(node);
  return node;
}

}  // namespace shaderport::glsl
