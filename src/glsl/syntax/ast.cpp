#include "glsl/syntax/ast.h"

#include <utility>

namespace shaderport::glsl {

SyntaxTree& SyntaxTree::operator=(SyntaxTree&& other) noexcept {
  if (this == &other) return *this;
  DestroyNodes();
  arena_ = std::move(other.arena_);
  nodes_ = std::exchange(other.nodes_, {});
  destructors_ = std::exchange(other.destructors_, {});
  root_ = std::exchange(other.root_, nullptr);
  preorder_ = std::exchange(other.preorder_, {});
  preorder_kinds_ = std::exchange(other.preorder_kinds_, {});
  preorder_index_ = std::exchange(other.preorder_index_, {});
  return *this;
}

void SyntaxTree::DestroyNodes() {
  // A node's destructor frees only what the node itself holds (names, vectors of
  // child pointers), never another node, so the order does not matter.
  for (const Destructor& destructor : destructors_) destructor.destroy(destructor.node);
  destructors_.clear();
  nodes_.clear();
  root_ = nullptr;
  preorder_.clear();
  preorder_kinds_.clear();
  preorder_index_.clear();
  arena_.reset();  // releases every block at once
}

const char* NodeKindName(NodeKind kind) {
  switch (kind) {
    case NodeKind::kTranslationUnit:
      return "translation-unit";
    case NodeKind::kTypeSpecifier:
      return "type-specifier";
    case NodeKind::kStructSpecifier:
      return "struct-specifier";
    case NodeKind::kVariableDeclaration:
      return "variable-declaration";
    case NodeKind::kDeclarator:
      return "declarator";
    case NodeKind::kQualifierDeclaration:
      return "qualifier-declaration";
    case NodeKind::kPrecisionDeclaration:
      return "precision-declaration";
    case NodeKind::kInterfaceBlock:
      return "interface-block";
    case NodeKind::kFunctionDeclaration:
      return "function-declaration";
    case NodeKind::kParameterDeclaration:
      return "parameter-declaration";
    case NodeKind::kCompoundStatement:
      return "compound-statement";
    case NodeKind::kExpressionStatement:
      return "expression-statement";
    case NodeKind::kIfStatement:
      return "if-statement";
    case NodeKind::kForStatement:
      return "for-statement";
    case NodeKind::kWhileStatement:
      return "while-statement";
    case NodeKind::kDoWhileStatement:
      return "do-while-statement";
    case NodeKind::kSwitchStatement:
      return "switch-statement";
    case NodeKind::kCaseLabel:
      return "case-label";
    case NodeKind::kBreakStatement:
      return "break-statement";
    case NodeKind::kContinueStatement:
      return "continue-statement";
    case NodeKind::kReturnStatement:
      return "return-statement";
    case NodeKind::kDiscardStatement:
      return "discard-statement";
    case NodeKind::kEmptyStatement:
      return "empty-statement";
    case NodeKind::kErrorStatement:
      return "error-statement";
    case NodeKind::kIdentifierExpr:
      return "identifier-expr";
    case NodeKind::kLiteralExpr:
      return "literal-expr";
    case NodeKind::kParenExpr:
      return "paren-expr";
    case NodeKind::kUnaryExpr:
      return "unary-expr";
    case NodeKind::kBinaryExpr:
      return "binary-expr";
    case NodeKind::kAssignmentExpr:
      return "assignment-expr";
    case NodeKind::kConditionalExpr:
      return "conditional-expr";
    case NodeKind::kCallExpr:
      return "call-expr";
    case NodeKind::kMemberExpr:
      return "member-expr";
    case NodeKind::kIndexExpr:
      return "index-expr";
    case NodeKind::kErrorExpr:
      return "error-expr";
  }
  return "?";
}

const char* UnaryOpSpelling(UnaryOp op) {
  switch (op) {
    case UnaryOp::kPlus:
      return "+";
    case UnaryOp::kMinus:
      return "-";
    case UnaryOp::kNot:
      return "!";
    case UnaryOp::kBitNot:
      return "~";
    case UnaryOp::kPreIncrement:
      return "++";
    case UnaryOp::kPreDecrement:
      return "--";
    case UnaryOp::kPostIncrement:
      return "++";
    case UnaryOp::kPostDecrement:
      return "--";
  }
  return "?";
}

const char* BinaryOpSpelling(BinaryOp op) {
  switch (op) {
    case BinaryOp::kMul:
      return "*";
    case BinaryOp::kDiv:
      return "/";
    case BinaryOp::kMod:
      return "%";
    case BinaryOp::kAdd:
      return "+";
    case BinaryOp::kSub:
      return "-";
    case BinaryOp::kShl:
      return "<<";
    case BinaryOp::kShr:
      return ">>";
    case BinaryOp::kLess:
      return "<";
    case BinaryOp::kGreater:
      return ">";
    case BinaryOp::kLessEqual:
      return "<=";
    case BinaryOp::kGreaterEqual:
      return ">=";
    case BinaryOp::kEqual:
      return "==";
    case BinaryOp::kNotEqual:
      return "!=";
    case BinaryOp::kBitAnd:
      return "&";
    case BinaryOp::kBitXor:
      return "^";
    case BinaryOp::kBitOr:
      return "|";
    case BinaryOp::kLogicalAnd:
      return "&&";
    case BinaryOp::kLogicalXor:
      return "^^";
    case BinaryOp::kLogicalOr:
      return "||";
    case BinaryOp::kComma:
      return ",";
  }
  return "?";
}

const char* AssignOpSpelling(AssignOp op) {
  switch (op) {
    case AssignOp::kAssign:
      return "=";
    case AssignOp::kMul:
      return "*=";
    case AssignOp::kDiv:
      return "/=";
    case AssignOp::kMod:
      return "%=";
    case AssignOp::kAdd:
      return "+=";
    case AssignOp::kSub:
      return "-=";
    case AssignOp::kShl:
      return "<<=";
    case AssignOp::kShr:
      return ">>=";
    case AssignOp::kBitAnd:
      return "&=";
    case AssignOp::kBitXor:
      return "^=";
    case AssignOp::kBitOr:
      return "|=";
  }
  return "?";
}

const char* PrecisionSpelling(Precision p) {
  switch (p) {
    case Precision::kNone:
      return "";
    case Precision::kLow:
      return "lowp";
    case Precision::kMedium:
      return "mediump";
    case Precision::kHigh:
      return "highp";
  }
  return "?";
}

const char* QualifierSpelling(QualifierKind kind) {
  switch (kind) {
    case QualifierKind::kConst:
      return "const";
    case QualifierKind::kIn:
      return "in";
    case QualifierKind::kOut:
      return "out";
    case QualifierKind::kInOut:
      return "inout";
    case QualifierKind::kUniform:
      return "uniform";
    case QualifierKind::kAttribute:
      return "attribute";
    case QualifierKind::kVarying:
      return "varying";
    case QualifierKind::kCentroid:
      return "centroid";
    case QualifierKind::kFlat:
      return "flat";
    case QualifierKind::kSmooth:
      return "smooth";
    case QualifierKind::kInvariant:
      return "invariant";
    case QualifierKind::kLayout:
      return "layout";
    case QualifierKind::kPrecision:
      return "precision";
  }
  return "?";
}

}  // namespace shaderport::glsl
