// The children of a syntax node in source order, as a template so that walks
// call their callback directly (inlined) instead of through std::function: the
// WebGL rules walk every node of every tree, and an indirect call per node and
// per child was most of their cost.
#pragma once

#include <vector>

#include "glsl/syntax/ast.h"

namespace shaderport::glsl {
namespace children_detail {

template <class Fn>
void Visit(const Node* node, Fn& fn) {
  if (node != nullptr) fn(*node);
}

template <class T, class Fn>
void VisitAll(const std::vector<T*>& nodes, Fn& fn) {
  for (const Node* node : nodes) Visit(node, fn);
}

template <class Fn>
void VisitArray(const std::vector<ArrayDimension>& array, Fn& fn) {
  for (const auto& dim : array) Visit(dim.size, fn);
}

template <class Fn>
void VisitQualifiers(const QualifierList& qualifiers, Fn& fn) {
  for (const auto& q : qualifiers.items) {
    for (const auto& id : q.layout_ids) Visit(id.value, fn);
  }
}

template <class Fn>
void ForEachChildOf(const Node& node, Fn& fn) {
  switch (node.kind) {
    case NodeKind::kTranslationUnit:
      return VisitAll(node.As<TranslationUnit>()->declarations, fn);
    case NodeKind::kTypeSpecifier: {
      const auto* n = node.As<TypeSpecifier>();
      Visit(n->struct_def, fn);
      return VisitArray(n->array, fn);
    }
    case NodeKind::kStructSpecifier:
      return VisitAll(node.As<StructSpecifier>()->fields, fn);
    case NodeKind::kVariableDeclaration: {
      const auto* n = node.As<VariableDeclaration>();
      VisitQualifiers(n->qualifiers, fn);
      Visit(n->type, fn);
      return VisitAll(n->declarators, fn);
    }
    case NodeKind::kDeclarator: {
      const auto* n = node.As<Declarator>();
      VisitArray(n->array, fn);
      return Visit(n->initializer, fn);
    }
    case NodeKind::kQualifierDeclaration:
      return VisitQualifiers(node.As<QualifierDeclaration>()->qualifiers, fn);
    case NodeKind::kPrecisionDeclaration:
      return Visit(node.As<PrecisionDeclaration>()->type, fn);
    case NodeKind::kInterfaceBlock: {
      const auto* n = node.As<InterfaceBlock>();
      VisitQualifiers(n->qualifiers, fn);
      VisitAll(n->members, fn);
      return VisitArray(n->instance_array, fn);
    }
    case NodeKind::kFunctionDeclaration: {
      const auto* n = node.As<FunctionDeclaration>();
      VisitQualifiers(n->qualifiers, fn);
      Visit(n->return_type, fn);
      VisitAll(n->parameters, fn);
      return Visit(n->body, fn);
    }
    case NodeKind::kParameterDeclaration: {
      const auto* n = node.As<ParameterDeclaration>();
      VisitQualifiers(n->qualifiers, fn);
      Visit(n->type, fn);
      return VisitArray(n->array, fn);
    }
    case NodeKind::kCompoundStatement:
      return VisitAll(node.As<CompoundStatement>()->statements, fn);
    case NodeKind::kExpressionStatement:
      return Visit(node.As<ExpressionStatement>()->expression, fn);
    case NodeKind::kIfStatement: {
      const auto* n = node.As<IfStatement>();
      Visit(n->condition, fn);
      Visit(n->then_branch, fn);
      return Visit(n->else_branch, fn);
    }
    case NodeKind::kForStatement: {
      const auto* n = node.As<ForStatement>();
      Visit(n->init, fn);
      Visit(n->condition, fn);
      Visit(n->increment, fn);
      return Visit(n->body, fn);
    }
    case NodeKind::kWhileStatement: {
      const auto* n = node.As<WhileStatement>();
      Visit(n->condition, fn);
      return Visit(n->body, fn);
    }
    case NodeKind::kDoWhileStatement: {
      const auto* n = node.As<DoWhileStatement>();
      Visit(n->body, fn);
      return Visit(n->condition, fn);
    }
    case NodeKind::kSwitchStatement: {
      const auto* n = node.As<SwitchStatement>();
      Visit(n->selector, fn);
      return Visit(n->body, fn);
    }
    case NodeKind::kCaseLabel:
      return Visit(node.As<CaseLabel>()->value, fn);
    case NodeKind::kReturnStatement:
      return Visit(node.As<ReturnStatement>()->value, fn);
    case NodeKind::kParenExpr:
      return Visit(node.As<ParenExpr>()->inner, fn);
    case NodeKind::kUnaryExpr:
      return Visit(node.As<UnaryExpr>()->operand, fn);
    case NodeKind::kBinaryExpr: {
      const auto* n = node.As<BinaryExpr>();
      Visit(n->lhs, fn);
      return Visit(n->rhs, fn);
    }
    case NodeKind::kAssignmentExpr: {
      const auto* n = node.As<AssignmentExpr>();
      Visit(n->lhs, fn);
      return Visit(n->rhs, fn);
    }
    case NodeKind::kConditionalExpr: {
      const auto* n = node.As<ConditionalExpr>();
      Visit(n->condition, fn);
      Visit(n->if_true, fn);
      return Visit(n->if_false, fn);
    }
    case NodeKind::kCallExpr: {
      const auto* n = node.As<CallExpr>();
      Visit(n->object, fn);
      Visit(n->constructor_type, fn);
      return VisitAll(n->arguments, fn);
    }
    case NodeKind::kMemberExpr:
      return Visit(node.As<MemberExpr>()->object, fn);
    case NodeKind::kIndexExpr: {
      const auto* n = node.As<IndexExpr>();
      Visit(n->base, fn);
      return Visit(n->index, fn);
    }
    case NodeKind::kBreakStatement:
    case NodeKind::kContinueStatement:
    case NodeKind::kDiscardStatement:
    case NodeKind::kEmptyStatement:
    case NodeKind::kErrorStatement:
    case NodeKind::kIdentifierExpr:
    case NodeKind::kLiteralExpr:
    case NodeKind::kErrorExpr:
      return;
  }
}

}  // namespace children_detail

/// Calls `fn(const Node&)` on each direct child of `node` in source order (null
/// slots skipped).
template <class Fn>
void ForEachChild(const Node& node, Fn&& fn) {
  children_detail::ForEachChildOf(node, fn);
}

}  // namespace shaderport::glsl
