#include "driver/port/emit_ported.h"

namespace shaderport::driver {
namespace {

// Text the port copied from the user's file maps back to it; text a rule
// inserted stays in the ported file, where the user can see it.
SourceRange ToUserRange(const SourceRange& range, const PortResult& result, FileId ported) {
  if (range.file != ported || !result.map.IsCopied(range.begin, range.end)) return range;
  const auto [begin, end] = result.map.ToOriginalRange(range.begin, range.end);
  return {result.file->Id(), begin, end};
}

}  // namespace

EmittedOutput EmitPorted(PortResult& result, const toolchain::EmitOptions& options,
                         SourceManager& sources) {
  EmittedOutput emitted;
  const SourceFile& ported = sources.Add(result.file->Name() + " (ported)", result.text, true);
  const toolchain::Stage stage = result.output_stage == Stage::kVertex
                                     ? toolchain::Stage::kVertex
                                     : toolchain::Stage::kFragment;
  toolchain::EmitOptions emit_options = options;
  emit_options.shadertoy = result.kind.dialect == Dialect::kShaderToy;
  toolchain::EmitResult leg = toolchain::Emit(ported, stage, emit_options);
  for (Diagnostic& diagnostic : leg.diagnostics) {
    diagnostic.range = ToUserRange(diagnostic.range, result, ported.Id());
    for (DiagnosticNote& note : diagnostic.notes) {
      note.range = ToUserRange(note.range, result, ported.Id());
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
