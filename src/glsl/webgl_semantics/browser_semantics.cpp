#include "glsl/webgl_semantics/browser_semantics.h"

#include <optional>
#include <string_view>
#include <vector>

#include "glsl/syntax/parser.h"
#include "glsl/syntax/visit.h"
#include "glsl/webgl_semantics/cpu_math_library.h"
#include "glsl/webgl_semantics/semantics_context.h"

namespace shaderport::glsl {

bool EditCollector::StartsExpansion(uint32_t token) const {
  return token == 0 || pp_.tokens[token - 1].expansion != pp_.tokens[token].expansion;
}

bool EditCollector::EndsExpansion(uint32_t token) const {
  return token + 1 >= pp_.tokens.size() ||
         pp_.tokens[token + 1].expansion != pp_.tokens[token].expansion;
}

std::optional<SourceRange> EditCollector::Span(const Node& node) const {
  if (!node.HasTokens() || node.last_token >= pp_.tokens.size()) return std::nullopt;
  const PpToken& first = pp_.tokens[node.first_token];
  const PpToken& last = pp_.tokens[node.last_token];
  const bool first_plain = first.macro_use == kNoMacroUse;
  const bool last_plain = last.macro_use == kNoMacroUse;
  if (!first_plain && !StartsExpansion(node.first_token)) return std::nullopt;
  if (!last_plain && !EndsExpansion(node.last_token)) return std::nullopt;
  const SourceRange begin = first_plain ? first.spelling : first.expansion;
  const SourceRange end = last_plain ? last.spelling : last.expansion;
  if (begin.file != end.file || begin.begin > end.end) return std::nullopt;
  return SourceRange{begin.file, begin.begin, end.end};
}

std::optional<SourceRange> EditCollector::AfterOpeningBrace(const CompoundStatement& body) const {
  if (!body.HasTokens()) return std::nullopt;
  const PpToken& brace = pp_.tokens[body.first_token];
  if (brace.macro_use != kNoMacroUse || brace.text != "{") return std::nullopt;
  return SourceRange{brace.spelling.file, brace.spelling.end, brace.spelling.end};
}

std::optional<SourceRange> EditCollector::BeforeClosingBrace(const CompoundStatement& body) const {
  if (!body.HasTokens()) return std::nullopt;
  const PpToken& brace = pp_.tokens[body.last_token];
  if (brace.macro_use != kNoMacroUse || brace.text != "}") return std::nullopt;
  return SourceRange{brace.spelling.file, brace.spelling.begin, brace.spelling.begin};
}

const FunctionDeclaration* FindMainDefinition(const SyntaxTree& tree) {
  for (const Node* node : tree.Root()->declarations) {
    const auto* function = node->As<FunctionDeclaration>();
    if (function != nullptr && function->body != nullptr && function->name.text == "main") {
      return function;
    }
  }
  return nullptr;
}

const Node* FirstFunctionDefinition(const SyntaxTree& tree) {
  for (const Node* node : tree.Root()->declarations) {
    const auto* function = node->As<FunctionDeclaration>();
    if (function != nullptr && function->body != nullptr) return node;
  }
  return nullptr;
}

namespace {

std::vector<uint32_t> ParentsOf(const SyntaxTree& tree) {
  std::vector<uint32_t> parent(tree.NodeCount(), kNoNode);
  VisitPreorder(tree, [&](const Node& node, uint32_t) {
    ForEachChild(node, [&](const Node& child) { parent[child.id] = node.id; });
    return true;
  });
  return parent;
}

}  // namespace

BrowserSemanticsResult ApplyBrowserSemantics(std::span<const SourceFile* const> parts,
                                             const BrowserSemanticsOptions& options) {
  BrowserSemanticsResult result;
  for (const SourceFile* part : parts) {
    result.texts.emplace_back(part->Text());
    result.maps.push_back(SourceMap::Identity(static_cast<uint32_t>(part->Text().size())));
  }
  const PreprocessResult preprocessed = Preprocess(parts);
  if (HasErrors(preprocessed.diagnostics)) return result;
  ParseOptions parse_options;
  parse_options.version = preprocessed.version.number;
  const ParseResult parsed = Parse(preprocessed, parse_options);
  if (HasErrors(parsed.diagnostics)) return result;
  AnalyzeOptions analyze;
  analyze.version = preprocessed.version.number;
  analyze.stage = options.vertex_stage ? model::Stage::kVertex : model::Stage::kFragment;
  const SemanticModel model = Analyze(parsed.tree, analyze);

  EditCollector edits(preprocessed);
  // Only the math helpers spell swizzles; other uses need not scan for defines.
  std::vector<std::string_view> texts;
  if (options.cpu_browser_math) {
    for (const SourceFile* part : parts) texts.push_back(part->Text());
  }
  SemanticsContext context{parsed.tree, model,  options, ParentsOf(parsed.tree),
                           edits,       result, nullptr, SwizzleLettersFreeOfMacros(texts)};
  std::optional<DriverFolding> folding;
  if (options.cpu_browser_math) {
    folding.emplace(parsed.tree, model, context.parent);
    context.folding = &*folding;
  }
  MainPrologue prologue;
  // Its helpers go in first where the smoothstep helper also goes; neither needs the other.
  if (options.cpu_browser_math) ComputeMathAsCpuBrowser(context, preprocessed);
  // Before the render probe, which writes `layout(location = 0) ` at the same place.
  if (options.source_order_arithmetic) KeepSourceOrderArithmetic(context);
  if (options.zero_initialize) {
    ZeroInitializeVariables(context, prologue);
    AddDefaultReturns(context, preprocessed);
  }
  if (options.empty_inactive_lines) EmptyInactiveLines(parts, preprocessed, edits);
  if (options.clamp_indices) ClampIndirectIndices(context);
  if (options.gpu_smoothstep_edges) RewriteSmoothstepEdges(context, preprocessed);
  if (options.promote_precision) PromotePrecision(context, preprocessed);
  if (options.add_render_probe && !options.vertex_stage) AddRenderProbe(context, prologue);
  if (!prologue.statements.empty()) {
    const FunctionDeclaration* main = FindMainDefinition(parsed.tree);
    const auto at = main != nullptr ? edits.AfterOpeningBrace(*main->body) : std::nullopt;
    if (at) {
      std::string text;
      for (const std::string& statement : prologue.statements) text += " " + statement;
      edits.Insert(at->file, at->begin, text);
    } else {
      ++result.skipped;
    }
  }

  for (size_t i = 0; i < parts.size(); ++i) {
    const auto found = edits.Edits().find(parts[i]->Id());
    if (found == edits.Edits().end()) continue;
    auto edited = ApplyEdits(parts[i]->Text(), found->second);
    if (!edited) {
      result.skipped += static_cast<uint32_t>(found->second.size());
      continue;
    }
    result.texts[i] = std::move(edited->text);
    result.maps[i] = std::move(edited->map);
  }
  result.applied = true;
  return result;
}

}  // namespace shaderport::glsl
