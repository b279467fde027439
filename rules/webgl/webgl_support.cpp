#include "rules/webgl/webgl_support.h"

#include <vector>

namespace shaderport::rules::webgl {

void ReportError(rule::RuleContext& context, std::string_view rule_id, const SourceRange& range,
                 std::string message, std::string note) {
  Diagnostic diagnostic =
      MakeDiagnostic(Severity::kError, std::string(rule_id), range, std::move(message));
  if (!note.empty()) diagnostic.notes.push_back({{}, std::move(note)});
  context.Report(std::move(diagnostic));
}

const glsl::Symbol* SymbolOf(const rule::RuleContext& context, const glsl::Node& node) {
  const uint32_t symbol = context.Model().SymbolAt(node.id);
  if (symbol == glsl::kNoSymbol) return nullptr;
  return &context.Model().symbols[symbol];
}

const glsl::Expr* Unparenthesized(const glsl::Expr* expr) {
  while (expr != nullptr && expr->kind == glsl::NodeKind::kParenExpr) {
    expr = static_cast<const glsl::ParenExpr*>(expr)->inner;
  }
  return expr;
}

std::optional<int64_t> LayoutLocation(const glsl::QualifierList& qualifiers) {
  for (const glsl::Qualifier& qualifier : qualifiers.items) {
    if (qualifier.kind != glsl::QualifierKind::kLayout) continue;
    for (const glsl::LayoutId& id : qualifier.layout_ids) {
      if (id.name.text != "location") continue;
      const glsl::Expr* value = Unparenthesized(id.value);
      const auto* literal = value == nullptr ? nullptr : value->As<glsl::LiteralExpr>();
      if (literal != nullptr && !literal->int_overflow &&
          literal->literal_kind == glsl::LiteralKind::kInt) {
        return static_cast<int64_t>(literal->int_value);
      }
    }
  }
  return std::nullopt;
}

bool StructContainsArray(const glsl::SemanticModel& model, const glsl::Type& type) {
  // Iterative: struct types cannot contain themselves, but stay bounded anyway.
  std::vector<glsl::Type> pending = {type};
  size_t visited = 0;
  while (!pending.empty() && visited++ < 4096) {
    const glsl::Type current = pending.back();
    pending.pop_back();
    if (current.base != glsl::BaseType::kStruct || current.struct_id >= model.structs.Size()) {
      continue;
    }
    for (const glsl::StructField& field : model.structs.Get(current.struct_id).fields) {
      if (field.type.IsArray()) return true;
      if (field.type.base == glsl::BaseType::kStruct) pending.push_back(field.type);
    }
  }
  return false;
}

}  // namespace shaderport::rules::webgl
