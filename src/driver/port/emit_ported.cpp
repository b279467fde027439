#include "driver/port/emit_ported.h"

#include "base/limits.h"
#include "driver/render_check/browser_render_text.h"
#include "driver/tree_depth.h"

namespace shaderport::driver {
namespace {

// Text the port copied from the user's file maps back to it; text a rule
// inserted stays in the ported file, where the user can see it.
SourceRange ToUserRange(const SourceRange& range, const SourceMap& map, FileId user,
                        FileId ported) {
  if (range.file != ported || !map.IsCopied(range.begin, range.end)) return range;
  const auto [begin, end] = map.ToOriginalRange(range.begin, range.end);
  return {user, begin, end};
}

}  // namespace

EmittedOutput EmitPorted(PortResult& result, const toolchain::EmitOptions& options,
                         SourceManager& sources) {
  EmittedOutput emitted;
  // Only the emit legs that compile to SPIR-V recurse over the tree.
  if (options.kind != toolchain::EmitKind::kEssl) {
    const uint32_t depth = SyntaxTreeDepth(result.text);
    if (depth > limits::kMaxSpirvTreeDepth) {
      result.diagnostics.push_back(MakeDiagnostic(
          Severity::kError, "spirv/tree-too-deep", {result.file->Id(), 0, 0},
          "not compiled to SPIR-V: the syntax tree is " + std::to_string(depth) +
              " levels deep, more than the " + std::to_string(limits::kMaxSpirvTreeDepth) +
              " allowed (docs/limits.md); split long expressions into statements"));
      return emitted;
    }
  }
  const model::Stage stage = result.output_stage;
  // Native targets do not zero-initialise or clamp indices as browsers do: the
  // leg compiles the port with the browser's semantics written out.
  BrowserRenderTextOptions semantics;
  semantics.vertex_stage = stage == model::Stage::kVertex;
  EditResult with_semantics = BrowserRenderTextWithMap(result.text, semantics);
  const SourceMap map = SourceMap::Compose(result.map, with_semantics.map);
  const SourceFile& ported =
      sources.Add(result.file->Name() + " (ported)", std::move(with_semantics.text), true);
  toolchain::EmitOptions emit_options = options;
  emit_options.shadertoy = result.kind.dialect == Dialect::kShaderToy;
  toolchain::EmitResult leg = toolchain::Emit(ported, stage, emit_options);
  for (Diagnostic& diagnostic : leg.diagnostics) {
    diagnostic.range = ToUserRange(diagnostic.range, map, result.file->Id(), ported.Id());
    for (DiagnosticNote& note : diagnostic.notes) {
      note.range = ToUserRange(note.range, map, result.file->Id(), ported.Id());
    }
    diagnostic.fixes.clear();  // the leg's findings carry no fixes for the user's text
    result.diagnostics.push_back(std::move(diagnostic));
  }
  emitted.words_before = leg.words_before;
  emitted.words_after = leg.words_after;
  if (HasErrors(leg.diagnostics)) return emitted;
  emitted.output = std::move(leg.output);
  emitted.extension = toolchain::EmitExtension(options.kind, stage);
  return emitted;
}

}  // namespace shaderport::driver
