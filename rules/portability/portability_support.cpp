#include "rules/portability/portability_support.h"

#include <array>

#include "glsl/sema/builtins.h"
#include "glsl/syntax/visit.h"

namespace shaderport::rules::portability {

const glsl::Expr* Unparenthesized(const glsl::Expr* expr) {
  while (expr != nullptr && expr->kind == glsl::NodeKind::kParenExpr) {
    expr = static_cast<const glsl::ParenExpr*>(expr)->inner;
  }
  return expr;
}

namespace {

ArgumentUse FromQualifier(glsl::ParamQualifier qualifier) {
  switch (qualifier) {
    case glsl::ParamQualifier::kOut:
      return ArgumentUse::kWrite;
    case glsl::ParamQualifier::kInOut:
      return ArgumentUse::kReadWrite;
    case glsl::ParamQualifier::kIn:
      break;
  }
  return ArgumentUse::kRead;
}

// An unresolved built-in call: unknown when some overload writes that argument.
ArgumentUse AnyBuiltinOverload(std::string_view name, size_t index) {
  for (const glsl::BuiltinFunction* overload : glsl::BuiltinOverloads(name)) {
    if (index < overload->params.size() &&
        overload->params[index].qualifier != glsl::ParamQualifier::kIn) {
      return ArgumentUse::kUnknown;
    }
  }
  return ArgumentUse::kRead;
}

}  // namespace

ArgumentUses::ArgumentUses(const rule::RuleContext& context, const glsl::CallExpr& call)
    : call_(call) {
  if (call.call_kind != glsl::CallKind::kFunction) {
    callee_ = Callee::kNotAFunction;
    return;
  }
  const glsl::SemanticModel& model = context.Model();
  if (const auto found = model.builtin_calls.find(call.id); found != model.builtin_calls.end()) {
    overload_ = found->second;
    callee_ = overload_ != nullptr ? Callee::kOverload : Callee::kAnyOverload;
    return;
  }
  const uint32_t symbol = model.SymbolAt(call.id);
  if (symbol == glsl::kNoSymbol || symbol >= model.symbols.size()) {
    callee_ =
        glsl::IsBuiltinFunctionName(call.callee.text) ? Callee::kAnyOverload : Callee::kUnknown;
    return;
  }
  const glsl::Symbol& function = model.symbols[symbol];
  if (function.kind == glsl::SymbolKind::kBuiltinFunction) {
    callee_ = Callee::kAnyOverload;
    return;
  }
  if (function.kind != glsl::SymbolKind::kFunction) return;
  const uint32_t node = function.declaration;
  if (node == glsl::kNoNode || node >= context.Tree().NodeCount()) return;
  declaration_ = context.Tree().NodeAt(node).As<glsl::FunctionDeclaration>();
  if (declaration_ != nullptr) callee_ = Callee::kDeclaration;
}

ArgumentUse ArgumentUses::Of(size_t index) const {
  switch (callee_) {
    case Callee::kNotAFunction:
      return ArgumentUse::kRead;
    case Callee::kOverload:
      if (index >= overload_->params.size()) return ArgumentUse::kRead;
      return FromQualifier(overload_->params[index].qualifier);
    case Callee::kAnyOverload:
      return AnyBuiltinOverload(call_.callee.text, index);
    case Callee::kDeclaration: {
      if (index >= declaration_->parameters.size()) return ArgumentUse::kRead;
      const glsl::QualifierList& qualifiers = declaration_->parameters[index]->qualifiers;
      if (qualifiers.Has(glsl::QualifierKind::kInOut)) return ArgumentUse::kReadWrite;
      if (qualifiers.Has(glsl::QualifierKind::kOut)) return ArgumentUse::kWrite;
      return ArgumentUse::kRead;
    }
    case Callee::kUnknown:
      break;
  }
  return ArgumentUse::kUnknown;
}

const glsl::IdentifierExpr* ChainRoot(const glsl::Expr* expr) {
  while (expr != nullptr) {
    switch (expr->kind) {
      case glsl::NodeKind::kParenExpr:
        expr = static_cast<const glsl::ParenExpr*>(expr)->inner;
        break;
      case glsl::NodeKind::kMemberExpr:
        expr = static_cast<const glsl::MemberExpr*>(expr)->object;
        break;
      case glsl::NodeKind::kIndexExpr:
        expr = static_cast<const glsl::IndexExpr*>(expr)->base;
        break;
      case glsl::NodeKind::kIdentifierExpr:
        return static_cast<const glsl::IdentifierExpr*>(expr);
      default:
        return nullptr;
    }
  }
  return nullptr;
}

std::optional<std::vector<int>> SwizzleComponents(std::string_view name) {
  static constexpr std::array<std::string_view, 3> kSets = {"xyzw", "rgba", "stpq"};
  if (name.empty() || name.size() > 4) return std::nullopt;
  for (std::string_view set : kSets) {
    std::vector<int> components;
    for (char c : name) {
      const size_t at = set.find(c);
      if (at == std::string_view::npos) break;
      components.push_back(static_cast<int>(at));
    }
    if (components.size() == name.size()) return components;
  }
  return std::nullopt;
}

void ForEachWrittenExpr(const rule::RuleContext& context, const glsl::Node& start,
                        const std::function<void(const glsl::Expr& target)>& fn) {
  constexpr glsl::NodeKinds kWriters = {glsl::NodeKind::kAssignmentExpr, glsl::NodeKind::kUnaryExpr,
                                        glsl::NodeKind::kCallExpr};
  glsl::ForEachNodeOf(context.Tree(), start, kWriters, [&](const glsl::Node& node) {
    if (const auto* assignment = node.As<glsl::AssignmentExpr>()) {
      if (assignment->lhs != nullptr) fn(*assignment->lhs);
    } else if (const auto* unary = node.As<glsl::UnaryExpr>()) {
      if (unary->op >= glsl::UnaryOp::kPreIncrement && unary->operand != nullptr) {
        fn(*unary->operand);
      }
    } else if (const auto* call = node.As<glsl::CallExpr>()) {
      const ArgumentUses uses(context, *call);
      for (size_t i = 0; i < call->arguments.size(); ++i) {
        if (call->arguments[i] != nullptr && uses.Of(i) != ArgumentUse::kRead) {
          fn(*call->arguments[i]);
        }
      }
    }
  });
}

bool InThisFile(const rule::RuleContext& context, const SourceRange& range) {
  return range.file == context.File().Id() && range.begin <= range.end &&
         range.end <= context.Text().size();
}

}  // namespace shaderport::rules::portability
