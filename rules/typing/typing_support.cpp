#include "rules/typing/typing_support.h"

#include <algorithm>
#include <unordered_set>

#include "glsl/sema/operator_typing.h"
#include "glsl/syntax/visit.h"

namespace shaderport::rules::typing {
namespace {

using glsl::CallExpr;
using glsl::Expr;
using glsl::MismatchContext;
using glsl::Type;

// The note for an int argument passed to an `out`/`inout` float parameter:
// `float(i)` is no l-value, so only the user can fix it.
std::string OutArgumentNote(const rule::RuleContext& context, const CallExpr& call, size_t index) {
  static const std::string kNote =
      "not fixed automatically: the parameter is 'out' or 'inout'; declare the argument as a float";
  const glsl::SemanticModel& model = context.Model();
  if (auto it = model.builtin_calls.find(call.id); it != model.builtin_calls.end()) {
    const auto& params = it->second->params;
    if (index < params.size() && params[index].qualifier != glsl::ParamQualifier::kIn) {
      return kNote;
    }
    return {};
  }
  const uint32_t symbol = model.SymbolAt(call.id);
  if (symbol == glsl::kNoSymbol || symbol >= model.symbols.size()) return {};
  const uint32_t declaration = model.symbols[symbol].declaration;
  if (declaration == glsl::kNoNode || declaration >= context.Tree().NodeCount()) return {};
  const auto* function = context.Tree().NodeAt(declaration).As<glsl::FunctionDeclaration>();
  if (function == nullptr || index >= function->parameters.size()) return {};
  const glsl::QualifierList& q = function->parameters[index]->qualifiers;
  if (q.Has(glsl::QualifierKind::kOut) || q.Has(glsl::QualifierKind::kInOut)) return kNote;
  return {};
}

// Array and struct constructors: GLSL ES converts nothing there, and the model
// records no mismatch for them.
void AddConstructorSites(const rule::RuleContext& context, const CallExpr& call,
                         std::vector<IntForFloatSite>& sites) {
  const glsl::SemanticModel& model = context.Model();
  const Type& type = model.TypeOf(call.id);
  auto add_if_int = [&](const Expr* argument, const Type& required, const char* where) {
    const Type& actual = model.TypeOf(argument->id);
    if (!actual.IsUnknown() && glsl::IntToFloat(actual) == required) {
      sites.push_back({argument, required, actual, where, {}});
    }
  };
  if (call.call_kind == glsl::CallKind::kConstructor && type.IsArray()) {
    for (const Expr* argument : call.arguments) {
      add_if_int(argument, type.Element(), "in an array constructor");
    }
    return;
  }
  if (!type.IsStruct()) return;
  if (call.call_kind == glsl::CallKind::kFunction) {
    const uint32_t symbol = model.SymbolAt(call.id);
    if (symbol == glsl::kNoSymbol || symbol >= model.symbols.size() ||
        model.symbols[symbol].kind != glsl::SymbolKind::kStruct) {
      return;  // a user function returning a struct
    }
  } else if (call.call_kind != glsl::CallKind::kConstructor) {
    return;
  }
  if (type.struct_id >= model.structs.Size()) return;
  const auto& fields = model.structs.Get(type.struct_id).fields;
  if (fields.size() != call.arguments.size()) return;
  for (size_t i = 0; i < fields.size(); ++i) {
    add_if_int(call.arguments[i], fields[i].type, "in a struct constructor");
  }
}

}  // namespace

std::vector<uint32_t> ParentMap(const glsl::SyntaxTree& tree) {
  std::vector<uint32_t> parents(tree.NodeCount(), glsl::kNoNode);
  if (tree.Root() == nullptr) return parents;
  glsl::VisitPreorder(tree, [&](const glsl::Node& node, uint32_t) {
    glsl::ForEachChild(node, [&](const glsl::Node& child) {
      if (child.id < parents.size()) parents[child.id] = node.id;
    });
    return true;
  });
  return parents;
}

const Expr* StripParensAndSign(const Expr* e) {
  while (e != nullptr) {
    if (const auto* paren = e->As<glsl::ParenExpr>()) {
      e = paren->inner;
    } else if (const auto* unary = e->As<glsl::UnaryExpr>();
               unary != nullptr &&
               (unary->op == glsl::UnaryOp::kMinus || unary->op == glsl::UnaryOp::kPlus)) {
      e = unary->operand;
    } else {
      break;
    }
  }
  return e;
}

const glsl::LiteralExpr* AsIntLiteral(const Expr* e) {
  const auto* literal =
      StripParensAndSign(e) == nullptr ? nullptr : StripParensAndSign(e)->As<glsl::LiteralExpr>();
  if (literal == nullptr || literal->literal_kind != glsl::LiteralKind::kInt) return nullptr;
  return literal;
}

std::optional<std::string> FloatSpelling(const glsl::LiteralExpr& literal) {
  if (literal.literal_kind != glsl::LiteralKind::kInt || literal.int_overflow) return std::nullopt;
  return std::to_string(literal.int_value) + ".0";
}

bool InThisFile(const rule::RuleContext& context, const SourceRange& range) {
  return range.file == context.File().Id() && range.begin <= range.end &&
         range.end <= context.Text().size();
}

SourceRange WrittenRange(const rule::RuleContext& context, const glsl::Node& node) {
  const auto& tokens = context.Preprocessed().tokens;
  if (!node.HasTokens() || node.last_token >= tokens.size()) return node.range;
  const glsl::PpToken& first = tokens[node.first_token];
  const glsl::PpToken& last = tokens[node.last_token];
  // Written inside one #define body: edit the body (the macro agreement check decides).
  if (first.in_macro_body && last.in_macro_body && first.macro_use == last.macro_use &&
      first.spelling.file == last.spelling.file && first.spelling.begin <= last.spelling.end) {
    return {first.spelling.file, first.spelling.begin, last.spelling.end};
  }
  // Part of a macro's expansion (a macro argument beside body tokens): its range is
  // the whole macro use, and an edit there would leave the node itself unchanged,
  // so the rule would ask again every round. Only a node that is a whole use maps.
  const bool expanded = first.expansion != first.spelling || last.expansion != last.spelling;
  if (expanded) {
    const bool starts_use =
        node.first_token == 0 || tokens[node.first_token - 1].expansion != first.expansion;
    const bool ends_use = node.last_token + 1 >= tokens.size() ||
                          tokens[node.last_token + 1].expansion != last.expansion;
    if (!starts_use || !ends_use) return {};
  }
  return node.range;
}

std::vector<FixIt> WrapInCall(const rule::RuleContext& context, const Expr& e,
                              std::string_view callee) {
  const SourceRange range = WrittenRange(context, e);
  if (!InThisFile(context, range) || range.begin == range.end) return {};
  const SourceRange before{range.file, range.begin, range.begin};
  if (e.kind == glsl::NodeKind::kParenExpr) return {{before, std::string(callee)}};
  const SourceRange after{range.file, range.end, range.end};
  return {{before, std::string(callee) + "("}, {after, ")"}};
}

const char* DescribeContext(MismatchContext context) {
  switch (context) {
    case MismatchContext::kInitializer:
      return "in an initializer";
    case MismatchContext::kAssignment:
      return "in an assignment";
    case MismatchContext::kReturn:
      return "in a return statement";
    case MismatchContext::kCallArgument:
      return "as a function argument";
    case MismatchContext::kBuiltinCallArgument:
      return "as a built-in function argument";
    case MismatchContext::kBinaryOperand:
      return "beside a float operand";
    case MismatchContext::kTernaryBranch:
      return "beside a float branch";
  }
  return "";
}

std::vector<IntForFloatSite> IntForFloatSites(const rule::RuleContext& context) {
  const glsl::SyntaxTree& tree = context.Tree();
  const glsl::SemanticModel& model = context.Model();
  std::vector<IntForFloatSite> sites;
  if (tree.Root() == nullptr) return sites;
  const std::vector<uint32_t> parents = ParentMap(tree);
  for (const glsl::TypeMismatch& m : model.mismatches) {
    if (m.kind != glsl::MismatchKind::kIntForFloat || m.node >= tree.NodeCount()) continue;
    const Expr* e = tree.NodeAt(m.node).As<Expr>();
    if (e == nullptr) continue;
    IntForFloatSite site{e, m.required, m.actual, DescribeContext(m.context), {}};
    const uint32_t parent = parents[m.node];
    if ((m.context == MismatchContext::kCallArgument ||
         m.context == MismatchContext::kBuiltinCallArgument) &&
        parent != glsl::kNoNode) {
      if (const auto* call = tree.NodeAt(parent).As<CallExpr>()) {
        auto it = std::find(call->arguments.begin(), call->arguments.end(), e);
        if (it != call->arguments.end()) {
          site.not_fixable_note = OutArgumentNote(context, *call, it - call->arguments.begin());
        }
      }
    }
    sites.push_back(std::move(site));
  }
  glsl::VisitPreorder(tree, [&](const glsl::Node& node, uint32_t) {
    if (const auto* call = node.As<CallExpr>()) AddConstructorSites(context, *call, sites);
    return true;
  });
  // One site per expression, in source order.
  std::unordered_set<uint32_t> seen;
  std::vector<IntForFloatSite> unique;
  for (IntForFloatSite& site : sites) {
    if (seen.insert(site.expr->id).second) unique.push_back(std::move(site));
  }
  std::stable_sort(unique.begin(), unique.end(), [](const auto& a, const auto& b) {
    return a.expr->range.begin < b.expr->range.begin;
  });
  return unique;
}

Diagnostic MakeDiagnostic(std::string_view rule_id, Severity severity, const SourceRange& range,
                          std::string message) {
  return shaderport::MakeDiagnostic(severity, std::string(rule_id), range, std::move(message));
}

}  // namespace shaderport::rules::typing
