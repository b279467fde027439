// `mediump` and `lowp` become `highp`: desktop browsers compute every precision at
// 32 bits (ANGLE on desktop drivers and SwiftShader), but Mesa lowers mediump to
// 16-bit floats, where e.g. `(310.0 + iTime) * 1000.0` overflows to infinity.
// Renamed wherever the keywords are spelled, macro bodies included.
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
}

}  // namespace shaderport::glsl
