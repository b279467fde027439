// port/frag-outputs: the GLSL ES 1.00 fragment outputs, which GLSL ES 3.00 removed,
// become declared `out` variables; gl_FragDepthEXT becomes gl_FragDepth.
//
// Before:                               After:
//   void main() {                         out highp vec4 fragColor;
//     gl_FragColor = vec4(1.0);           void main() {
//   }                                       fragColor = vec4(1.0);
//                                         }
//   gl_FragData[1] = n;                   layout(location = 1) out highp vec4 fragData1;
//                                         ... fragData1 = n;
//
// The output's name is fresh: used nowhere in the shader (fragColor, else
// fragColor_1, ...). A gl_FragData index that is not a constant is reported
// without a fix. The declarations go before the first function of the file.
#include <map>
#include <optional>
#include <unordered_map>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/port/port_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "port/frag-outputs";

// Uses of the built-in variable `name`, in source order.
std::vector<uint32_t> BuiltinUses(const rule::RuleContext& context, std::string_view name) {
  std::vector<uint32_t> uses;
  const auto& model = context.Model();
  for (uint32_t symbol : model.FindSymbols(name)) {
    if (model.symbols[symbol].kind != glsl::SymbolKind::kBuiltinVariable) continue;
    for (uint32_t node : model.UsesOf(symbol)) uses.push_back(node);
  }
  return uses;
}

std::optional<int64_t> ConstantIndex(const rule::RuleContext& context, const glsl::Expr* index) {
  while (index != nullptr && index->kind == glsl::NodeKind::kParenExpr) {
    index = index->As<glsl::ParenExpr>()->inner;
  }
  if (index == nullptr) return std::nullopt;
  if (const auto* literal = index->As<glsl::LiteralExpr>()) {
    if (literal->literal_kind == glsl::LiteralKind::kInt && !literal->int_overflow) {
      return static_cast<int64_t>(literal->int_value);
    }
    return std::nullopt;
  }
  if (index->kind == glsl::NodeKind::kIdentifierExpr) {
    const uint32_t symbol = context.Model().SymbolAt(index->id);
    if (symbol != glsl::kNoSymbol) return context.Model().symbols[symbol].const_value;
  }
  return std::nullopt;
}

// Where output declarations go: the start of the line of the file's first function.
std::optional<uint32_t> DeclarationPoint(const rule::RuleContext& context) {
  for (const glsl::Node* node : context.Tree().Root()->declarations) {
    if (node->kind == glsl::NodeKind::kFunctionDeclaration &&
        webgl2::InThisFile(context, node->range)) {
      const SourceFile& file = context.File();
      return file.LineStart(file.LocationOf(node->range.begin).line);
    }
  }
  return std::nullopt;
}

class FragOutputsRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "Declare fragment outputs instead of gl_FragColor and gl_FragData",
        "void main() { gl_FragColor = vec4(1.0); }",
        "out highp vec4 fragColor;\nvoid main() { fragColor = vec4(1.0); }",
        rule::RuleScope::kPort};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    if (context.Settings().stage != model::Stage::kFragment) return;
    if (context.Tree().Root() == nullptr) return;
    const std::optional<uint32_t> point = DeclarationPoint(context);
    FragColor(context, point);
    FragData(context, point);
    FragDepth(context);
  }

 private:
  static void FragColor(rule::RuleContext& context, std::optional<uint32_t> point) {
    const auto uses = BuiltinUses(context, "gl_FragColor");
    if (uses.empty()) return;
    const auto& tree = context.Tree();
    const std::string name = webgl2::FreshName(context, "fragColor");
    auto diagnostic = webgl2::MakeDiagnostic(
        kId, Severity::kWarning, tree.NodeAt(uses.front()).range,
        "gl_FragColor does not exist in GLSL ES 3.00; write to a declared 'out' variable ('" +
            name + "')");
    if (point) {
      diagnostic.fixes.push_back(
          webgl2::Insert(context.File().Id(), *point, "out highp vec4 " + name + ";\n"));
      for (uint32_t use : uses) {
        const glsl::Node& node = tree.NodeAt(use);
        diagnostic.fixes.push_back(
            webgl2::Replace(webgl2::NameFixRange(context, node, node.range, "gl_FragColor"), name));
      }
    }
    webgl2::ReportSplittingMacroBodies(context, std::move(diagnostic));
  }

  static void FragData(rule::RuleContext& context, std::optional<uint32_t> point) {
    const auto uses = BuiltinUses(context, "gl_FragData");
    if (uses.empty()) return;
    const auto& tree = context.Tree();
    // The IndexExpr around each use, if any.
    std::unordered_map<uint32_t, const glsl::IndexExpr*> index_of;
    glsl::VisitPreorder(tree, [&](const glsl::Node& node, uint32_t) {
      if (const auto* index = node.As<glsl::IndexExpr>(); index && index->base) {
        index_of[index->base->id] = index;
      }
      return true;
    });
    std::map<int64_t, std::string> outputs;  // index -> fresh name
    std::vector<std::pair<const glsl::IndexExpr*, int64_t>> renames;
    for (uint32_t use : uses) {
      const auto it = index_of.find(use);
      const std::optional<int64_t> n =
          it == index_of.end() ? std::nullopt : ConstantIndex(context, it->second->index);
      if (!n || *n < 0 || *n > 255) {
        context.Report(webgl2::MakeDiagnostic(
            kId, Severity::kError, tree.NodeAt(use).range,
            "gl_FragData needs a constant index to become a GLSL ES 3.00 output; declare "
            "'layout(location = N) out vec4' outputs and write them by name"));
        return;
      }
      renames.emplace_back(it->second, *n);
      if (!outputs.contains(*n)) outputs[*n] = "";
    }
    for (auto& [n, name] : outputs) {
      name = webgl2::FreshName(context, "fragData" + std::to_string(n));
    }
    auto diagnostic = webgl2::MakeDiagnostic(
        kId, Severity::kWarning, tree.NodeAt(uses.front()).range,
        "gl_FragData does not exist in GLSL ES 3.00; write to declared 'out' variables");
    if (point) {
      std::string declarations;
      for (const auto& [n, name] : outputs) {
        declarations +=
            "layout(location = " + std::to_string(n) + ") out highp vec4 " + name + ";\n";
      }
      diagnostic.fixes.push_back(webgl2::Insert(context.File().Id(), *point, declarations));
      for (const auto& [index, n] : renames) {
        diagnostic.fixes.push_back(webgl2::Replace(index->range, outputs[n]));
      }
    }
    webgl2::ReportSplittingMacroBodies(context, std::move(diagnostic));
  }

  static void FragDepth(rule::RuleContext& context) {
    for (uint32_t use : BuiltinUses(context, "gl_FragDepthEXT")) {
      const glsl::Node& node = context.Tree().NodeAt(use);
      auto diagnostic = webgl2::MakeDiagnostic(kId, Severity::kWarning, node.range,
                                               "gl_FragDepthEXT is gl_FragDepth in GLSL ES 3.00");
      diagnostic.fixes.push_back(webgl2::Replace(
          webgl2::NameFixRange(context, node, node.range, "gl_FragDepthEXT"), "gl_FragDepth"));
      webgl2::ReportSplittingMacroBodies(context, std::move(diagnostic));
    }
  }
};

}  // namespace

const rule::Rule& PortFragOutputsRule() {
  static const FragOutputsRule rule;
  return rule;
}

}  // namespace shaderport::rules
