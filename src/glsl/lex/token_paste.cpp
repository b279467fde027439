#include <string>

#include "glsl/lex/lexer.h"
#include "glsl/lex/macro_expander.h"

namespace shaderport::glsl {

bool PasteTokens(PpState& state, const PpToken& left, const PpToken& right, PpToken* pasted) {
  std::string text(left.text);
  text += right.text;
  // Relex the joined text: the paste is valid only when it is exactly one token.
  const SourceFile scratch(kNoFile, "<paste>", text);
  const LexedFile lexed = Lex(scratch);
  if (lexed.tokens.size() != 2 || !lexed.trivia.empty() || !lexed.diagnostics.empty()) {
    return false;
  }
  const Token& t = lexed.tokens[0];
  *pasted = left;
  pasted->kind = t.kind;
  pasted->punct = t.punct;
  if (t.kind == TokenKind::kHash) {  // a pasted '#' never starts a directive
    pasted->kind = TokenKind::kPunctuator;
    pasted->punct = Punct::kHashInLine;
  }
  pasted->text = state.Store(std::move(text));
  pasted->spelling = Cover(left.spelling, right.spelling);
  pasted->in_macro_body = true;
  return true;
}

}  // namespace shaderport::glsl
