#include <string>

#include "glsl/lex/lexer.h"
#include "glsl/lex/preprocessor.h"

namespace shaderport::glsl {
namespace {

std::string Where(const SourceManager& sources, SourceRange range) {
  if (!range.Valid() || range.file >= sources.Size()) return "?";
  const SourceFile& file = sources.Get(range.file);
  const LineColumn at = file.LocationOf(range.begin);
  return file.Name() + ":" + std::to_string(at.line) + ":" + std::to_string(at.column);
}

}  // namespace

std::string DumpPpTokens(const PreprocessResult& result, const SourceManager& sources) {
  std::string out;
  for (const PpToken& t : result.tokens) {
    out += Where(sources, t.expansion) + " " + TokenKindName(t.kind) + " '" +
           EscapeForDump(t.text) + "'";
    if (t.macro_use != kNoMacroUse) {
      out += " <- spelled " + Where(sources, t.spelling) + " via ";
      // Innermost macro first; the chain is bounded by the number of uses.
      uint32_t use = t.macro_use;
      for (size_t n = 0; use < result.macro_uses.size() && n <= result.macro_uses.size(); ++n) {
        out += (n ? " < " : "") + result.macro_uses[use].name;
        use = result.macro_uses[use].parent;
      }
    }
    out += '\n';
  }
  return out;
}

}  // namespace shaderport::glsl
