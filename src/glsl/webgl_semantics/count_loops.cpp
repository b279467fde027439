// Instrumentation, not a browser behaviour: every loop body starts by counting
// itself into a global and writing the count to an extra fragment output, so a
// render can tell whether llvmpipe's silent cap of 65535 loop iterations per
// invocation was reached (the picture then is not what a browser draws).
// Multiple fragment outputs need explicit locations in GLSL ES 3.00, so the probe
// is only added when the shader has exactly one output, which gets location 0.
#include "glsl/sema/language.h"
#include "glsl/syntax/visit.h"
#include "glsl/webgl_semantics/semantics_context.h"

namespace shaderport::glsl {
namespace {

constexpr std::string_view kCounter = "shaderport_loop_count";

struct Output {
  const VariableDeclaration* declaration = nullptr;
  bool has_layout = false;
};

// The fragment outputs; nullopt when the probe cannot be added next to them.
std::optional<Output> SingleOutput(const SyntaxTree& tree) {
  std::optional<Output> found;
  for (const Node* node : tree.Root()->declarations) {
    const auto* decl = node->As<VariableDeclaration>();
    if (decl == nullptr || !decl->qualifiers.Has(QualifierKind::kOut)) continue;
    if (found || decl->declarators.size() != 1) return std::nullopt;
    found = Output{decl, decl->qualifiers.Has(QualifierKind::kLayout)};
  }
  return found;
}

std::string CountStatement() {
  return std::string(" ") + std::string(kLoopProbeOutput) + ".x = float(++" +
         std::string(kCounter) + ");";
}

}  // namespace

void CountLoopIterations(SemanticsContext& c, MainPrologue& prologue) {
  if (c.model.version < kEssl300) return;
  const auto output = SingleOutput(c.tree);
  if (!output || output->has_layout) return;  // an explicit layout may use location 1
  const FunctionDeclaration* main = FindMainDefinition(c.tree);
  const auto* first_function = [&]() -> const Node* {
    for (const Node* node : c.tree.Root()->declarations) {
      const auto* function = node->As<FunctionDeclaration>();
      if (function != nullptr && function->body != nullptr) return node;
    }
    return nullptr;
  }();
  const auto output_span = c.edits.Span(*output->declaration);
  const auto declare_at = first_function ? c.edits.Span(*first_function) : std::nullopt;
  if (main == nullptr || !output_span || !declare_at) return;

  // Collect the loop edits first: nothing is added when a loop cannot be counted.
  std::vector<std::pair<SourceRange, std::string>> loop_edits;
  bool complete = true;
  uint32_t loops = 0;
  VisitPreorder(c.tree, [&](const Node& node, uint32_t) {
    const Node* body = nullptr;
    if (const auto* loop = node.As<ForStatement>()) body = loop->body;
    if (const auto* loop = node.As<WhileStatement>()) body = loop->body;
    if (const auto* loop = node.As<DoWhileStatement>()) body = loop->body;
    if (body == nullptr) return true;
    ++loops;
    if (const auto* compound = body->As<CompoundStatement>()) {
      const auto at = c.edits.AfterOpeningBrace(*compound);
      if (!at) complete = false;
      if (at) loop_edits.emplace_back(*at, CountStatement());
      return true;
    }
    const auto span = c.edits.Span(*body);
    if (!span) {
      complete = false;
      return true;
    }
    loop_edits.emplace_back(SourceRange{span->file, span->begin, span->begin},
                            "{" + CountStatement() + " ");
    loop_edits.emplace_back(SourceRange{span->file, span->end, span->end}, " }");
    return true;
  });
  if (!complete || loops == 0) return;
  for (auto& [at, text] : loop_edits) c.edits.Insert(at.file, at.begin, std::move(text));
  c.edits.Insert(output_span->file, output_span->begin, "layout(location = 0) ");
  c.edits.Insert(declare_at->file, declare_at->begin,
                 "layout(location = 1) out highp vec4 " + std::string(kLoopProbeOutput) + "; int " +
                     std::string(kCounter) + " = 0; ");
  prologue.statements.push_back(std::string(kLoopProbeOutput) + " = vec4(0.0);");
  c.result.counted_loops = loops;
  c.result.loop_probe = true;
}

}  // namespace shaderport::glsl
