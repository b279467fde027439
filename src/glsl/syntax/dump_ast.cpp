// DumpAst: one line per node for golden tests and `shaderport dump --ast`.
#include <algorithm>
#include <string>

#include "glsl/syntax/parser.h"
#include "glsl/syntax/visit.h"

namespace shaderport::glsl {
namespace {

std::string Quote(std::string_view text) { return "'" + std::string(text) + "'"; }

std::string Qualifiers(const QualifierList& list) {
  std::string out;
  for (const auto& q : list.items) {
    out += " ";
    if (q.kind == QualifierKind::kPrecision) {
      out += PrecisionSpelling(q.precision);
      continue;
    }
    out += QualifierSpelling(q.kind);
    if (q.kind != QualifierKind::kLayout) continue;
    out += "(";
    for (size_t i = 0; i < q.layout_ids.size(); ++i) {
      if (i > 0) out += ",";
      out += q.layout_ids[i].name.text;
      if (q.layout_ids[i].value != nullptr) out += "=";
    }
    out += ")";
  }
  return out;
}

std::string Dims(const std::vector<ArrayDimension>& array) {
  std::string out;
  for (const auto& dim : array) out += dim.size != nullptr ? "[N]" : "[]";
  return out;
}

const char* TypeNameKindName(TypeNameKind kind) {
  switch (kind) {
    case TypeNameKind::kBuiltin:
      return "builtin";
    case TypeNameKind::kStruct:
      return "struct";
    case TypeNameKind::kUnknown:
      return "unknown";
  }
  return "?";
}

std::string Attributes(const Node& node) {
  switch (node.kind) {
    case NodeKind::kIdentifierExpr:
      return " " + node.As<IdentifierExpr>()->name;
    case NodeKind::kLiteralExpr:
      return " " + node.As<LiteralExpr>()->text;
    case NodeKind::kUnaryExpr: {
      const auto* n = node.As<UnaryExpr>();
      bool postfix = n->op == UnaryOp::kPostIncrement || n->op == UnaryOp::kPostDecrement;
      return std::string(postfix ? " postfix " : " prefix ") + UnaryOpSpelling(n->op);
    }
    case NodeKind::kBinaryExpr:
      return " " + Quote(BinaryOpSpelling(node.As<BinaryExpr>()->op));
    case NodeKind::kAssignmentExpr:
      return " " + Quote(AssignOpSpelling(node.As<AssignmentExpr>()->op));
    case NodeKind::kCallExpr: {
      const auto* n = node.As<CallExpr>();
      const char* kind = n->call_kind == CallKind::kFunction      ? " function "
                         : n->call_kind == CallKind::kConstructor ? " constructor "
                                                                  : " method ";
      return kind + n->callee.text + (n->void_argument ? " (void)" : "");
    }
    case NodeKind::kMemberExpr:
      return " ." + node.As<MemberExpr>()->member.text;
    case NodeKind::kTypeSpecifier: {
      const auto* n = node.As<TypeSpecifier>();
      std::string out = " ";
      if (n->precision != Precision::kNone)
        out += std::string(PrecisionSpelling(n->precision)) + " ";
      return out + (n->name.Empty() ? "<anonymous>" : n->name.text) + Dims(n->array) + " (" +
             TypeNameKindName(n->name_kind) + ")";
    }
    case NodeKind::kStructSpecifier: {
      const auto* n = node.As<StructSpecifier>();
      return " " + (n->name.Empty() ? std::string("<anonymous>") : n->name.text);
    }
    case NodeKind::kVariableDeclaration:
      return Qualifiers(node.As<VariableDeclaration>()->qualifiers);
    case NodeKind::kDeclarator: {
      const auto* n = node.As<Declarator>();
      return " " + n->name.text + Dims(n->array) + (n->initializer != nullptr ? " =" : "");
    }
    case NodeKind::kQualifierDeclaration: {
      const auto* n = node.As<QualifierDeclaration>();
      std::string out = Qualifiers(n->qualifiers);
      for (const auto& name : n->names) out += " " + name.text;
      return out;
    }
    case NodeKind::kPrecisionDeclaration:
      return std::string(" ") + PrecisionSpelling(node.As<PrecisionDeclaration>()->precision);
    case NodeKind::kInterfaceBlock: {
      const auto* n = node.As<InterfaceBlock>();
      std::string out = Qualifiers(n->qualifiers) + " " + n->block_name.text;
      if (!n->instance_name.Empty()) out += " " + n->instance_name.text + Dims(n->instance_array);
      return out;
    }
    case NodeKind::kFunctionDeclaration: {
      const auto* n = node.As<FunctionDeclaration>();
      return Qualifiers(n->qualifiers) + " " + n->name.text + (n->void_parameter ? " (void)" : "") +
             (n->body != nullptr ? " definition" : " prototype");
    }
    case NodeKind::kParameterDeclaration: {
      const auto* n = node.As<ParameterDeclaration>();
      return Qualifiers(n->qualifiers) + (n->name.Empty() ? "" : " " + n->name.text) +
             Dims(n->array);
    }
    case NodeKind::kCaseLabel:
      return node.As<CaseLabel>()->value == nullptr ? " default" : " case";
    default:
      return "";
  }
}

std::string RangeText(const SourceRange& range, const SourceManager& sources) {
  if (!range.Valid() || range.file >= sources.Size()) return "<no range>";
  const SourceFile& file = sources.Get(range.file);
  LineColumn begin = file.LocationOf(range.begin);
  LineColumn end = file.LocationOf(range.end);
  std::string prefix = sources.Size() > 1 ? file.Name() + ":" : "";
  return prefix + std::to_string(begin.line) + ":" + std::to_string(begin.column) + "-" +
         std::to_string(end.line) + ":" + std::to_string(end.column);
}

}  // namespace

std::string DumpAst(const SyntaxTree& tree, const SourceManager& sources) {
  std::string out;
  VisitPreorder(tree, [&](const Node& node, uint32_t depth) {
    // Indentation stops growing so that a chain of thousands of operators
    // stays linear in size; deeper lines carry their depth instead.
    constexpr uint32_t kMaxIndent = 64;
    out.append(2 * std::min(depth, kMaxIndent), ' ');
    if (depth > kMaxIndent) out += "[" + std::to_string(depth) + "] ";
    out += NodeKindName(node.kind);
    out += Attributes(node);
    out += " ";
    out += RangeText(node.range, sources);
    out += "\n";
    return true;
  });
  return out;
}

}  // namespace shaderport::glsl
