#include "glsl/webgl_semantics/browser_semantics.h"

#include <algorithm>
#include <cctype>
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

// One-line `#define NAME...` lines of `text`: where each starts and ends, by name.
struct DefineLine {
  std::string_view name;
  uint32_t begin = 0;
  uint32_t body = 0;  // just after the name
  uint32_t end = 0;   // at the '\n' (or the text's end)
};

std::vector<DefineLine> DefineLines(std::string_view text) {
  std::vector<DefineLine> lines;
  const auto blank = [&](size_t at) {
    while (at < text.size() && (text[at] == ' ' || text[at] == '\t')) ++at;
    return at;
  };
  for (size_t begin = 0; begin < text.size();) {
    size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    size_t at = blank(begin);
    if (at < end && text[at] == '#') {
      at = blank(at + 1);
      if (text.compare(at, 6, "define") == 0 && blank(at + 6) > at + 6) {
        const size_t name = blank(at + 6);
        size_t name_end = name;
        while (name_end < end && (std::isalnum(static_cast<unsigned char>(text[name_end])) != 0 ||
                                  text[name_end] == '_')) {
          ++name_end;
        }
        const bool continued = end > begin && text[end - (text[end - 1] == '\r' ? 2 : 1)] == '\\';
        if (name_end > name && !continued) {
          lines.push_back({text.substr(name, name_end - name), static_cast<uint32_t>(begin),
                           static_cast<uint32_t>(name_end), static_cast<uint32_t>(end)});
        }
      }
    }
    begin = end + 1;
  }
  return lines;
}

// An edit inside a macro's body (a built-in renamed there) changes the definition the
// uses expand from; a shader may define the macro again, identically, which is legal
// until the two differ, and then Mesa refuses the redefinition (ShaderToy tlXfDS). The
// same edit goes into every identical definition of that macro in the part.
// Only definitions our preprocessor read (outside skipped groups, whose lines other
// edits empty), and only edits inside a body.
void MirrorEditsIntoIdenticalDefinitions(std::string_view text, FileId part,
                                         const PreprocessResult& preprocessed,
                                         std::vector<Edit>& edits) {
  std::vector<DefineLine> defines = DefineLines(text);
  std::erase_if(defines, [&](const DefineLine& line) {
    return std::any_of(preprocessed.inactive_regions.begin(), preprocessed.inactive_regions.end(),
                       [&](const SourceRange& r) {
                         return r.file == part && r.begin <= line.begin && line.begin < r.end;
                       });
  });
  if (defines.size() < 2) return;
  std::vector<Edit> added;
  for (const Edit& edit : edits) {
    for (const DefineLine& line : defines) {
      if (edit.begin < line.body || edit.end > line.end) continue;
      const std::string_view spelled = text.substr(line.begin, line.end - line.begin);
      for (const DefineLine& other : defines) {
        if (other.begin == line.begin || other.name != line.name ||
            text.substr(other.begin, other.end - other.begin) != spelled) {
          continue;
        }
        const Edit mirrored{edit.begin - line.begin + other.begin,
                            edit.end - line.begin + other.begin, edit.text};
        if (std::find(edits.begin(), edits.end(), mirrored) == edits.end() &&
            std::find(added.begin(), added.end(), mirrored) == added.end()) {
          added.push_back(mirrored);
        }
      }
      break;
    }
  }
  edits.insert(edits.end(), added.begin(), added.end());
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
    std::vector<Edit> part_edits = found->second;
    MirrorEditsIntoIdenticalDefinitions(parts[i]->Text(), parts[i]->Id(), preprocessed, part_edits);
    auto edited = ApplyEdits(parts[i]->Text(), part_edits);
    if (!edited) {
      result.skipped += static_cast<uint32_t>(part_edits.size());
      continue;
    }
    result.texts[i] = std::move(edited->text);
    result.maps[i] = std::move(edited->map);
  }
  result.applied = true;
  return result;
}

}  // namespace shaderport::glsl
