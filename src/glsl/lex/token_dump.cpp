#include <cstdio>
#include <string>

#include "glsl/lex/lexer.h"

namespace shaderport::glsl {

const char* TokenKindName(TokenKind kind) {
  switch (kind) {
    case TokenKind::kEndOfFile:
      return "eof";
    case TokenKind::kIdentifier:
      return "identifier";
    case TokenKind::kIntLiteral:
      return "int";
    case TokenKind::kUintLiteral:
      return "uint";
    case TokenKind::kFloatLiteral:
      return "float";
    case TokenKind::kPunctuator:
      return "punctuator";
    case TokenKind::kHash:
      return "hash";
    case TokenKind::kInvalid:
      return "invalid";
  }
  return "?";
}

const char* TriviaKindName(TriviaKind kind) {
  switch (kind) {
    case TriviaKind::kWhitespace:
      return "whitespace";
    case TriviaKind::kNewline:
      return "newline";
    case TriviaKind::kLineComment:
      return "line-comment";
    case TriviaKind::kBlockComment:
      return "block-comment";
    case TriviaKind::kLineContinuation:
      return "line-continuation";
    case TriviaKind::kSkipped:
      return "skipped";
  }
  return "?";
}

std::string RemoveLineContinuations(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && i + 1 < text.size() && (text[i + 1] == '\n' || text[i + 1] == '\r')) {
      ++i;
      if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      continue;
    }
    out.push_back(text[i]);
  }
  return out;
}

std::string EscapeForDump(std::string_view text) {
  std::string out;
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\\' || c == '\'') {
      out += '\\';
      out += ch;
    } else if (c >= 0x20 && c < 0x7F) {
      out += ch;
    } else {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\x%02X", c);
      out += buffer;
    }
  }
  return out;
}

std::string DumpTokens(const SourceFile& file, const LexedFile& lexed) {
  std::string out;
  for (const Token& token : lexed.tokens) {
    const LineColumn at = file.LocationOf(token.begin);
    out += std::to_string(at.line) + ":" + std::to_string(at.column) + " " +
           TokenKindName(token.kind) + " '" + EscapeForDump(token.text) + "'\n";
  }
  return out;
}

}  // namespace shaderport::glsl
