// `mediump` and `lowp` become `highp`: desktop browsers compute every precision at
// 32 bits (ANGLE on desktop drivers and SwiftShader), but Mesa lowers mediump to
// 16-bit floats, where e.g. `(310.0 + iTime) * 1000.0` overflows to infinity.
// Renamed wherever the keywords are spelled, macro bodies included. A fragment
// shader's default int precision is mediump when it declares none (GLSL ES 3.00
// section 4.5.4), so `precision highp int; ` goes in front of its first declaration.
#include <set>
#include <utility>

#include "glsl/sema/language.h"
#include "glsl/webgl_semantics/semantics_context.h"

namespace shaderport::glsl {

void PromotePrecision(SemanticsContext& c, const PreprocessResult& preprocessed) {
  if (c.model.version < kEssl300) return;  // ES 1.00 fragment shaders may lack highp
  std::set<std::pair<FileId, uint32_t>> done;
  for (const PpToken& token : preprocessed.tokens) {
    if (token.text != "mediump" && token.text != "lowp") continue;
    if (token.spelling.Size() != token.text.size()) continue;  // pasted with ##
    if (!done.insert({token.spelling.file, token.spelling.begin}).second) continue;
    c.edits.Replace(token.spelling, "highp");
    ++c.result.promoted;
  }
  if (c.options.vertex_stage || c.tree.Root() == nullptr || c.tree.Root()->declarations.empty()) {
    return;
  }
  for (const Node* node : c.tree.Root()->declarations) {
    const auto* precision = node->As<PrecisionDeclaration>();
    if (precision != nullptr && precision->type != nullptr && precision->type->name.text == "int") {
      return;  // declared: made highp above if it was not
    }
  }
  const auto first = c.edits.Span(*c.tree.Root()->declarations.front());
  if (!first) {
    ++c.result.skipped;
    return;
  }
  c.edits.Insert(first->file, first->begin, "precision highp int; ");
  ++c.result.promoted;
}

}  // namespace shaderport::glsl
