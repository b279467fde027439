// A function that can run off its end without `return` (a `switch` without
// `default`, an `if` without `else`) returns zero in the browser: measured in
// Chromium, `float f(int i) { if (i == 0) return 0.25; }` gives 0 for i = 1, and a
// struct or vector comes back all zero. GLSL leaves the value undefined and
// llvmpipe hands back whatever was computed last, so every non-void function
// definition gets ` return <zero>;` before its closing brace (unreachable, and
// harmless, where the body already returns).
#include "glsl/webgl_semantics/semantics_context.h"
#include "glsl/webgl_semantics/zero_value.h"

namespace shaderport::glsl {

void AddDefaultReturns(SemanticsContext& c, const PreprocessResult& preprocessed) {
  for (const Node* node : c.tree.Root()->declarations) {
    const auto* function = node->As<FunctionDeclaration>();
    if (function == nullptr || function->body == nullptr || !function->body->HasTokens()) {
      continue;
    }
    const uint32_t symbol = c.model.SymbolAt(function->id);
    if (symbol >= c.model.symbols.size()) continue;
    const Type& type = c.model.symbols[symbol].type;
    if (type.IsVoid() || type.IsUnknown()) continue;
    const auto zero = ZeroValue(type, c.model.structs, c.model.version);
    const PpToken& brace = preprocessed.tokens[function->body->last_token];
    if (!zero || brace.text != "}" || brace.macro_use != kNoMacroUse) {
      ++c.result.skipped;
      continue;
    }
    c.edits.Insert(brace.spelling.file, brace.spelling.begin, " return " + *zero + "; ");
    ++c.result.default_returns;
  }
}

}  // namespace shaderport::glsl
