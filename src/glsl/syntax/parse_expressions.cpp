// Expressions, by precedence climbing (GLSL ES 3.00 section 5.1).
#include <charconv>
#include <optional>
#include <string>

#include "glsl/syntax/parser_internal.h"

namespace shaderport::glsl {
namespace {

struct BinaryInfo {
  BinaryOp op;
  int precedence;
};

std::optional<BinaryInfo> BinaryOf(const PpToken& t) {
  if (t.kind != TokenKind::kPunctuator) return std::nullopt;
  switch (t.punct) {
    case Punct::kOrOr:
      return BinaryInfo{BinaryOp::kLogicalOr, 1};
    case Punct::kXorXor:
      return BinaryInfo{BinaryOp::kLogicalXor, 2};
    case Punct::kAndAnd:
      return BinaryInfo{BinaryOp::kLogicalAnd, 3};
    case Punct::kPipe:
      return BinaryInfo{BinaryOp::kBitOr, 4};
    case Punct::kCaret:
      return BinaryInfo{BinaryOp::kBitXor, 5};
    case Punct::kAmp:
      return BinaryInfo{BinaryOp::kBitAnd, 6};
    case Punct::kEqualEqual:
      return BinaryInfo{BinaryOp::kEqual, 7};
    case Punct::kNotEqual:
      return BinaryInfo{BinaryOp::kNotEqual, 7};
    case Punct::kLess:
      return BinaryInfo{BinaryOp::kLess, 8};
    case Punct::kGreater:
      return BinaryInfo{BinaryOp::kGreater, 8};
    case Punct::kLessEqual:
      return BinaryInfo{BinaryOp::kLessEqual, 8};
    case Punct::kGreaterEqual:
      return BinaryInfo{BinaryOp::kGreaterEqual, 8};
    case Punct::kShiftLeft:
      return BinaryInfo{BinaryOp::kShl, 9};
    case Punct::kShiftRight:
      return BinaryInfo{BinaryOp::kShr, 9};
    case Punct::kPlus:
      return BinaryInfo{BinaryOp::kAdd, 10};
    case Punct::kMinus:
      return BinaryInfo{BinaryOp::kSub, 10};
    case Punct::kStar:
      return BinaryInfo{BinaryOp::kMul, 11};
    case Punct::kSlash:
      return BinaryInfo{BinaryOp::kDiv, 11};
    case Punct::kPercent:
      return BinaryInfo{BinaryOp::kMod, 11};
    default:
      return std::nullopt;
  }
}

std::optional<AssignOp> AssignOf(const PpToken& t) {
  if (t.kind != TokenKind::kPunctuator) return std::nullopt;
  switch (t.punct) {
    case Punct::kEqual:
      return AssignOp::kAssign;
    case Punct::kStarEqual:
      return AssignOp::kMul;
    case Punct::kSlashEqual:
      return AssignOp::kDiv;
    case Punct::kPercentEqual:
      return AssignOp::kMod;
    case Punct::kPlusEqual:
      return AssignOp::kAdd;
    case Punct::kMinusEqual:
      return AssignOp::kSub;
    case Punct::kShiftLeftEqual:
      return AssignOp::kShl;
    case Punct::kShiftRightEqual:
      return AssignOp::kShr;
    case Punct::kAmpEqual:
      return AssignOp::kBitAnd;
    case Punct::kCaretEqual:
      return AssignOp::kBitXor;
    case Punct::kPipeEqual:
      return AssignOp::kBitOr;
    default:
      return std::nullopt;
  }
}

std::optional<UnaryOp> PrefixOf(const PpToken& t) {
  if (t.kind != TokenKind::kPunctuator) return std::nullopt;
  switch (t.punct) {
    case Punct::kPlus:
      return UnaryOp::kPlus;
    case Punct::kMinus:
      return UnaryOp::kMinus;
    case Punct::kBang:
      return UnaryOp::kNot;
    case Punct::kTilde:
      return UnaryOp::kBitNot;
    case Punct::kPlusPlus:
      return UnaryOp::kPreIncrement;
    case Punct::kMinusMinus:
      return UnaryOp::kPreDecrement;
    default:
      return std::nullopt;
  }
}

// Decimal, octal (leading 0) or hex integer with an optional u/U suffix.
void ParseIntegerText(std::string_view text, LiteralExpr* literal) {
  if (!text.empty() && (text.back() == 'u' || text.back() == 'U')) text.remove_suffix(1);
  int base = 10;
  if (text.size() > 1 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
    base = 16;
    text.remove_prefix(2);
  } else if (text.size() > 1 && text[0] == '0') {
    base = 8;
    text.remove_prefix(1);
  }
  uint64_t value = 0;
  for (char c : text) {
    int digit = c >= '0' && c <= '9' ? c - '0' : (c | 0x20) - 'a' + 10;
    if (digit < 0 || digit >= base) break;  // the lexer reports malformed literals
    value = value * static_cast<uint64_t>(base) + static_cast<uint64_t>(digit);
    if (value > 0xFFFFFFFFull) {
      literal->int_overflow = true;
      value &= 0xFFFFFFFFull;
    }
  }
  literal->int_value = value;
}

}  // namespace

Expr* Parser::ParseExpression() {
  uint32_t first = Index();
  Expr* lhs = ParseAssignment();
  while (AtPunct(Punct::kComma)) {
    auto* node = tree_.Make<BinaryExpr>();
    node->first_token = first;
    node->op = BinaryOp::kComma;
    node->op_range = Tok().expansion;
    node->lhs = lhs;
    Advance();
    node->rhs = ParseAssignment();
    lhs = Finish(node);
  }
  return lhs;
}

Expr* Parser::ParseAssignment() {
  DepthGuard guard(*this);
  if (TooDeep()) {
    auto* error = Start<ErrorExpr>();
    SkipBalanced(false);
    return Finish(error);
  }
  uint32_t first = Index();
  Expr* lhs = ParseConditional();
  std::optional<AssignOp> op = AssignOf(Tok());
  if (!op) return lhs;
  auto* node = tree_.Make<AssignmentExpr>();
  node->first_token = first;
  node->op = *op;
  node->op_range = Tok().expansion;
  node->lhs = lhs;
  Advance();
  BrowserStackGuard stack(*this, browser_stack::kAssignedValue);
  node->rhs = ParseAssignment();
  return Finish(node);
}

Expr* Parser::ParseConditional() {
  uint32_t first = Index();
  Expr* condition = ParseBinary(1);
  if (!AtPunct(Punct::kQuestion)) return condition;
  auto* node = tree_.Make<ConditionalExpr>();
  node->first_token = first;
  node->condition = condition;
  Advance();
  {
    BrowserStackGuard stack(*this, browser_stack::kConditionalTrue);
    node->if_true = ParseExpression();
  }
  Expect(Punct::kColon, "in conditional expression");
  BrowserStackGuard stack(*this, browser_stack::kConditionalFalse);
  node->if_false = ParseAssignment();
  return Finish(node);
}

Expr* Parser::ParseBinary(int min_precedence) {
  uint32_t first = Index();
  Expr* lhs = ParseUnary();
  while (true) {
    std::optional<BinaryInfo> info = BinaryOf(Tok());
    if (!info || info->precedence < min_precedence) return lhs;
    auto* node = tree_.Make<BinaryExpr>();
    node->first_token = first;
    node->op = info->op;
    node->op_range = Tok().expansion;
    node->lhs = lhs;
    Advance();
    BrowserStackGuard stack(*this, browser_stack::kRightOperand);
    node->rhs = ParseBinary(info->precedence + 1);
    lhs = Finish(node);
  }
}

Expr* Parser::ParseUnary() {
  std::optional<UnaryOp> op = PrefixOf(Tok());
  if (!op) return ParsePostfix();
  DepthGuard guard(*this);
  BrowserStackGuard stack(*this, browser_stack::kPrefixOperator);
  auto* node = Start<UnaryExpr>();
  node->op = *op;
  node->op_range = Tok().expansion;
  Advance();
  if (TooDeep()) {
    node->operand = Start<ErrorExpr>();
    SkipBalanced(false);
    Finish(node->operand);
  } else {
    node->operand = ParseUnary();
  }
  return Finish(node);
}

Expr* Parser::ParsePostfix() {
  uint32_t first = Index();
  Expr* expr = ParsePrimary();
  while (true) {
    if (AtPunct(Punct::kLeftBracket)) {
      auto* node = tree_.Make<IndexExpr>();
      node->first_token = first;
      node->base = expr;
      Advance();
      {
        BrowserStackGuard stack(*this, browser_stack::kIndex);
        node->index = ParseExpression();
      }
      if (!Expect(Punct::kRightBracket, "to close the index")) {
        SkipBalanced(false);
        Accept(Punct::kRightBracket);
      }
      expr = Finish(node);
    } else if (AtPunct(Punct::kDot)) {
      Advance();
      Name member = Tok().kind == TokenKind::kIdentifier
                        ? Name{std::string(Text()), Tok().expansion}
                        : ExpectName("a field name after '.'");
      if (Tok().kind == TokenKind::kIdentifier) Advance();
      if (AtPunct(Punct::kLeftParen)) {
        auto* call = tree_.Make<CallExpr>();
        call->first_token = first;
        call->call_kind = CallKind::kMethod;
        call->object = expr;
        call->callee = std::move(member);
        ParseArguments(call);
        expr = Finish(call);
      } else {
        auto* node = tree_.Make<MemberExpr>();
        node->first_token = first;
        node->object = expr;
        node->member = std::move(member);
        expr = Finish(node);
      }
    } else if (AtPunct(Punct::kPlusPlus) || AtPunct(Punct::kMinusMinus)) {
      auto* node = tree_.Make<UnaryExpr>();
      node->first_token = first;
      node->op = AtPunct(Punct::kPlusPlus) ? UnaryOp::kPostIncrement : UnaryOp::kPostDecrement;
      node->op_range = Tok().expansion;
      node->operand = expr;
      Advance();
      expr = Finish(node);
    } else {
      return expr;
    }
  }
}

bool Parser::AtConstructor() const { return IsTypeName(); }

Expr* Parser::ParsePrimary() {
  const PpToken& t = Tok();
  if (t.kind == TokenKind::kIntLiteral || t.kind == TokenKind::kUintLiteral ||
      t.kind == TokenKind::kFloatLiteral || AtRole(WordRole::kBoolLiteral)) {
    return ParseLiteral();
  }
  if (AtPunct(Punct::kLeftParen)) {
    auto* node = Start<ParenExpr>();
    Advance();
    {
      BrowserStackGuard stack(*this, browser_stack::kParenthesis);
      node->inner = ParseExpression();
    }
    if (!Expect(Punct::kRightParen, "to match '('")) {
      SkipBalanced(false);
      Accept(Punct::kRightParen);
    }
    return Finish(node);
  }
  if (AtConstructor() || (AtName() && AtPunct(Punct::kLeftParen, 1))) {
    return ParseConstructorOrCall();
  }
  if (AtName()) {
    auto* node = Start<IdentifierExpr>();
    node->name = TakeName().text;
    return Finish(node);
  }
  if (t.kind != TokenKind::kInvalid) {  // the lexer already reported invalid bytes
    ErrorAtToken("syntax/expected-expression", "expected expression, found " + Describe());
  }
  return MakeErrorExpr();
}

Expr* Parser::ParseLiteral() {
  auto* node = Start<LiteralExpr>();
  node->text = std::string(Text());
  switch (Tok().kind) {
    case TokenKind::kIntLiteral:
      node->literal_kind = LiteralKind::kInt;
      ParseIntegerText(node->text, node);
      break;
    case TokenKind::kUintLiteral:
      node->literal_kind = LiteralKind::kUint;
      ParseIntegerText(node->text, node);
      break;
    case TokenKind::kFloatLiteral: {
      node->literal_kind = LiteralKind::kFloat;
      std::string_view text = node->text;
      if (!text.empty() && (text.back() == 'f' || text.back() == 'F')) text.remove_suffix(1);
      std::from_chars(text.data(), text.data() + text.size(), node->float_value);
      break;
    }
    default:
      node->literal_kind = LiteralKind::kBool;
      node->bool_value = node->text == "true";
      break;
  }
  Advance();
  return Finish(node);
}

Expr* Parser::ParseConstructorOrCall() {
  auto* call = Start<CallExpr>();
  if (IsTypeName()) {
    call->call_kind = CallKind::kConstructor;
    call->constructor_type = ParseTypeSpecifier({});
    call->callee = call->constructor_type->name;
  } else {
    call->callee = TakeName();
  }
  if (AtPunct(Punct::kLeftParen)) {
    ParseArguments(call);
  } else {
    ErrorAtToken("syntax/expected-token",
                 "expected '(' after type name '" + call->callee.text + "', found " + Describe());
  }
  return Finish(call);
}

void Parser::ParseArguments(CallExpr* call) {
  Advance();  // `(`
  if (AtKeyword("void") && AtPunct(Punct::kRightParen, 1)) {
    call->void_argument = true;
    Advance();
  } else if (!AtPunct(Punct::kRightParen)) {
    while (true) {
      BrowserStackGuard stack(*this, call->arguments.empty() ? browser_stack::kFirstArgument
                                                             : browser_stack::kLaterArgument);
      call->arguments.push_back(ParseAssignment());
      if (!Accept(Punct::kComma)) break;
    }
  }
  if (!Expect(Punct::kRightParen, "to close the argument list")) {
    SkipBalanced(false);
    Accept(Punct::kRightParen);
  }
}

}  // namespace shaderport::glsl
