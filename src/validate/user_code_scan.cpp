#include "validate/user_code_scan.h"

#include <algorithm>

namespace shaderport::validate {
namespace {

using glsl::Punct;
using glsl::Token;
using glsl::TokenKind;

bool IsWordOrPunct(const Token& token) {
  return token.kind == TokenKind::kIdentifier || token.kind == TokenKind::kPunctuator ||
         token.kind == TokenKind::kHash;
}

bool IsBlank(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v'; }

// Index of the token after the directive that starts at `hash` (the next line start).
size_t EndOfDirective(const glsl::LexedFile& lexed, size_t hash) {
  size_t i = hash + 1;
  while (i < lexed.tokens.size() && lexed.tokens[i].kind != TokenKind::kEndOfFile &&
         !lexed.tokens[i].at_line_start) {
    ++i;
  }
  return i;
}

std::string_view DirectiveName(const glsl::LexedFile& lexed, size_t hash) {
  const size_t next = hash + 1;
  if (next >= lexed.tokens.size() || lexed.tokens[next].at_line_start ||
      lexed.tokens[next].kind != TokenKind::kIdentifier) {
    return {};
  }
  return lexed.tokens[next].text;
}

}  // namespace

SourceRange LocateOnLine(const SourceFile& file, const glsl::LexedFile& lexed, uint32_t line,
                         std::string_view token) {
  line = std::clamp<uint32_t>(line, 1, file.LineCount());
  const uint32_t line_begin = file.LineStart(line);
  const std::string_view text = file.LineText(line);
  const uint32_t line_end = line_begin + static_cast<uint32_t>(text.size());
  if (!token.empty()) {
    // Tokens are sorted by offset: a binary search finds the line's first one.
    auto it = std::lower_bound(lexed.tokens.begin(), lexed.tokens.end(), line_begin,
                               [](const Token& t, uint32_t offset) { return t.begin < offset; });
    for (; it != lexed.tokens.end() && it->begin < line_end; ++it) {
      if (IsWordOrPunct(*it) && it->text == token) return {file.Id(), it->begin, it->end};
    }
  }
  uint32_t first = 0;
  uint32_t last = static_cast<uint32_t>(text.size());
  while (first < last && IsBlank(text[first])) ++first;
  while (last > first && IsBlank(text[last - 1])) --last;
  return {file.Id(), line_begin + first, line_begin + last};
}

OpenConstructs CountOpenConstructs(const glsl::LexedFile& lexed) {
  OpenConstructs open;
  for (size_t i = 0; i < lexed.tokens.size(); ++i) {
    const Token& token = lexed.tokens[i];
    if (token.kind == TokenKind::kHash) {
      const std::string_view name = DirectiveName(lexed, i);
      if (name == "if" || name == "ifdef" || name == "ifndef") ++open.conditionals;
      if (name == "endif") --open.conditionals;
      i = EndOfDirective(lexed, i) - 1;
      continue;
    }
    if (token.kind != TokenKind::kPunctuator) continue;
    if (token.punct == Punct::kLeftBrace) ++open.braces;
    if (token.punct == Punct::kRightBrace) --open.braces;
    if (token.punct == Punct::kLeftParen) ++open.parens;
    if (token.punct == Punct::kRightParen) --open.parens;
  }
  return open;
}

bool HasUnbalancedMacroBody(const glsl::LexedFile& lexed) {
  return MacroBodyOpens(lexed, Punct::kLeftParen, Punct::kRightParen);
}

bool MacroBodyOpens(const glsl::LexedFile& lexed, Punct open, Punct close) {
  for (size_t i = 0; i < lexed.tokens.size(); ++i) {
    if (lexed.tokens[i].kind != TokenKind::kHash || DirectiveName(lexed, i) != "define") continue;
    const size_t end = EndOfDirective(lexed, i);
    size_t body = i + 3;  // after '#', 'define' and the macro name
    // A '(' right after the name (no space) opens the parameter list, not the body.
    if (body < end && lexed.tokens[body].punct == Punct::kLeftParen &&
        !lexed.tokens[body].leading_space) {
      while (body < end && lexed.tokens[body].punct != Punct::kRightParen) ++body;
      ++body;
    }
    int depth = 0;
    for (size_t k = body; k < end; ++k) {
      if (lexed.tokens[k].punct == open) ++depth;
      if (lexed.tokens[k].punct == close) --depth;
    }
    if (depth > 0) return true;
    i = end - 1;
  }
  return false;
}

void CollectUserMacros(const glsl::LexedFile& lexed, FileId file, std::vector<UserMacro>& defined) {
  for (size_t i = 0; i < lexed.tokens.size(); ++i) {
    if (lexed.tokens[i].kind != TokenKind::kHash) continue;
    const std::string_view directive = DirectiveName(lexed, i);
    const size_t end = EndOfDirective(lexed, i);
    if ((directive == "define" || directive == "undef") && i + 2 < end &&
        lexed.tokens[i + 2].kind == TokenKind::kIdentifier) {
      const Token& name = lexed.tokens[i + 2];
      std::erase_if(defined, [&](const UserMacro& m) { return m.name == name.text; });
      if (directive == "define") defined.push_back({file, name.text, name.begin, name.end});
    }
    i = end - 1;
  }
}

namespace {

// Calls `fn` on each token outside preprocessor directives, in order, until it
// returns false.
template <class Fn>
void ForEachCodeToken(const glsl::LexedFile& lexed, Fn fn) {
  for (size_t i = 0; i < lexed.tokens.size(); ++i) {
    const Token& token = lexed.tokens[i];
    if (token.kind == TokenKind::kEndOfFile) return;
    if (token.kind == TokenKind::kHash && token.at_line_start) {
      i = EndOfDirective(lexed, i) - 1;
      continue;
    }
    if (!fn(token)) return;
  }
}

}  // namespace

const glsl::Token* LastCodeToken(const glsl::LexedFile& lexed) {
  const Token* last = nullptr;
  ForEachCodeToken(lexed, [&](const Token& token) {
    last = &token;
    return true;
  });
  return last;
}

const glsl::Token* FirstCodeToken(const glsl::LexedFile& lexed) {
  const Token* first = nullptr;
  ForEachCodeToken(lexed, [&](const Token& token) {
    first = &token;
    return false;
  });
  return first;
}

uint32_t FirstCodeLine(const SourceFile& file, const glsl::LexedFile& lexed) {
  const Token* first = FirstCodeToken(lexed);
  return first == nullptr ? 0 : file.LocationOf(first->begin).line;
}

}  // namespace shaderport::validate
