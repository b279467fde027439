#include "glsl/lex/lexer.h"

#include <cstdio>
#include <cstring>
#include <string>

#include "base/limits.h"
#include "glsl/lex/lex_chars.h"
#include "glsl/lex/punctuators_internal.h"

namespace shaderport::glsl {
namespace {

class Lexer {
 public:
  explicit Lexer(const SourceFile& file)
      : file_(file),
        text_(file.Text()),
        // Most files have no backslash: then no line continuation can split a token or
        // a comment, and the loops below may read bytes directly.
        plain_(text_.empty() || std::memchr(text_.data(), '\\', text_.size()) == nullptr) {}

  LexedFile Run() {
    // Shaders have about one token and one trivia per five bytes: room for that up
    // front saves most regrowths (and their copies) of the two arrays.
    out_.tokens.reserve(text_.size() / 5 + 1);
    out_.trivia.reserve(text_.size() / 5 + 1);
    size_t p = 0;
    while (true) {
      p = LexTrivia(p);
      if (p >= text_.size()) break;
      if (token_count_ >= limits::kMaxTokens) {
        Report("lex/too-many-tokens", p, text_.size(),
               "the file has more than " + std::to_string(limits::kMaxTokens) +
                   " tokens; the rest of it is not read");
        out_.trivia.push_back({TriviaKind::kSkipped, U32(p), U32(text_.size())});
        p = text_.size();
        break;
      }
      p = LexToken(p);
    }
    Finish(TokenKind::kEndOfFile, Punct::kNone, text_.size(), text_.size());
    return std::move(out_);
  }

 private:
  static uint32_t U32(size_t v) { return static_cast<uint32_t>(v); }

  // Consumes the trivia starting at `p`; returns where the next token starts.
  size_t LexTrivia(size_t p) {
    const size_t n = text_.size();
    while (p < n) {
      const char c = text_[p];
      size_t end = p;
      TriviaKind kind;
      if (IsHorizontalSpace(c)) {
        while (end < n && IsHorizontalSpace(text_[end])) ++end;
        kind = TriviaKind::kWhitespace;
        leading_space_ = true;
      } else if (size_t nl = NewlineLength(text_, p)) {
        end = p + nl;
        kind = TriviaKind::kNewline;
        at_line_start_ = true;
        leading_space_ = false;
      } else if (size_t lc = plain_ ? 0 : ContinuationLength(text_, p)) {
        end = p + lc;
        kind = TriviaKind::kLineContinuation;
      } else if (c == '/' && PeekLogical(text_, p, 1) == '/') {
        end = plain_ ? PlainLineCommentEnd(p) : LineCommentEnd(text_, p);
        kind = TriviaKind::kLineComment;
        leading_space_ = true;
      } else if (c == '/' && PeekLogical(text_, p, 1) == '*') {
        end = plain_ ? PlainBlockCommentEnd(p) : BlockCommentEnd(text_, p);
        if (end == kNoEnd) {
          end = n;
          Report("lex/unterminated-comment", p, p + 2,
                 "unterminated /* comment: it runs to the end of the file");
        }
        kind = TriviaKind::kBlockComment;
        leading_space_ = true;
      } else {
        break;
      }
      out_.trivia.push_back({kind, U32(p), U32(end)});
      p = end;
    }
    return p;
  }

  // Lexes one token at `p` (not trivia); returns where it ends.
  size_t LexToken(size_t p) {
    TokenKind kind;
    Punct punct = Punct::kNone;
    Cursor cursor(text_, p);
    const char c = text_[p];
    if (IsIdentifierStart(c)) {
      kind = TokenKind::kIdentifier;
      if (plain_) {
        size_t end = p + 1;
        while (end < text_.size() && IsIdentifierChar(text_[end])) ++end;
        cursor.SetEnd(end);
      } else {
        while (IsIdentifierChar(cursor.Ch())) cursor.Bump();
      }
    } else if (IsDigit(c) || (c == '.' && IsDigit(cursor.Peek(1)))) {
      kind = LexNumber(cursor);
    } else if (c == '#' && at_line_start_) {
      kind = TokenKind::kHash;
      cursor.Bump();
    } else if (int length = 0;
               (punct = MatchPunctuator(c, PeekFrom(cursor, p, 1), PeekFrom(cursor, p, 2),
                                        &length)) != Punct::kNone) {
      kind = TokenKind::kPunctuator;
      if (plain_) {
        cursor.SetEnd(p + static_cast<size_t>(length));
      } else {
        for (int i = 0; i < length; ++i) cursor.Bump();
      }
    } else {
      kind = TokenKind::kInvalid;
      cursor.SetEnd(p + InvalidLength(text_, p));
      ReportInvalid(p, cursor.End());
    }
    Finish(kind, punct, p, cursor.End());
    return cursor.End();
  }

  // The logical character `k` after `p` (where `cursor` stands); '\0' past the end.
  char PeekFrom(const Cursor& cursor, size_t p, size_t k) const {
    if (!plain_) return cursor.Peek(static_cast<int>(k));
    return p + k < text_.size() ? text_[p + k] : '\0';
  }

  // LineCommentEnd and BlockCommentEnd for a file without backslashes.
  size_t PlainLineCommentEnd(size_t p) const {
    const char* begin = text_.data() + p;
    const size_t rest = text_.size() - p;
    const void* lf = std::memchr(begin, '\n', rest);
    const size_t until = lf ? static_cast<size_t>(static_cast<const char*>(lf) - begin) : rest;
    const void* cr = std::memchr(begin, '\r', until);
    return p + (cr ? static_cast<size_t>(static_cast<const char*>(cr) - begin) : until);
  }
  size_t PlainBlockCommentEnd(size_t p) const {
    const size_t close = text_.find("*/", p + 2);
    return close == std::string_view::npos ? kNoEnd : close + 2;
  }

  static TokenKind LexNumber(Cursor& cursor) {
    TokenKind kind = TokenKind::kIntLiteral;
    const char x = cursor.Peek(1);
    if (cursor.Ch() == '0' && (x == 'x' || x == 'X')) {
      cursor.Bump();
      cursor.Bump();
      while (IsHexDigit(cursor.Ch())) cursor.Bump();
    } else {
      while (IsDigit(cursor.Ch())) cursor.Bump();
      if (cursor.Ch() == '.') {
        kind = TokenKind::kFloatLiteral;
        cursor.Bump();
        while (IsDigit(cursor.Ch())) cursor.Bump();
      }
      const char e1 = cursor.Peek(1);
      const bool exponent = (cursor.Ch() == 'e' || cursor.Ch() == 'E') &&
                            (IsDigit(e1) || ((e1 == '+' || e1 == '-') && IsDigit(cursor.Peek(2))));
      if (exponent) {
        kind = TokenKind::kFloatLiteral;
        cursor.Bump();
        if (!IsDigit(cursor.Ch())) cursor.Bump();  // the sign
        while (IsDigit(cursor.Ch())) cursor.Bump();
      }
      if (kind == TokenKind::kFloatLiteral && (cursor.Ch() == 'f' || cursor.Ch() == 'F')) {
        cursor.Bump();
      }
    }
    if (kind == TokenKind::kIntLiteral && (cursor.Ch() == 'u' || cursor.Ch() == 'U')) {
      cursor.Bump();
      kind = TokenKind::kUintLiteral;
    }
    return kind;
  }

  void ReportInvalid(size_t begin, size_t end) {
    // A run of adjacent invalid characters gets one diagnostic.
    if (!out_.tokens.empty() && out_.tokens.back().kind == TokenKind::kInvalid &&
        out_.tokens.back().end == begin && !out_.diagnostics.empty() &&
        out_.diagnostics.back().rule_id == "lex/invalid-character" &&
        out_.diagnostics.back().range.end == begin) {
      out_.diagnostics.back().range.end = U32(end);
      return;
    }
    Report("lex/invalid-character", begin, end, DescribeInvalid(text_.substr(begin, end - begin)));
  }

  void Report(const char* rule, size_t begin, size_t end, std::string message) {
    if (out_.diagnostics.size() >= limits::kMaxDiagnosticsPerFile) {
      auto& last = out_.diagnostics.back();
      if (last.notes.empty()) last.notes.push_back({{}, "further lexer diagnostics were dropped"});
      return;
    }
    Diagnostic d;
    d.severity = Severity::kError;
    d.rule_id = rule;
    d.range = {file_.Id(), U32(begin), U32(end)};
    d.message = std::move(message);
    out_.diagnostics.push_back(std::move(d));
  }

  // Stores the token of bytes [begin, end) with the pending trivia and line flags,
  // written in place (a token built aside and then copied cost a copy per token).
  void Finish(TokenKind kind, Punct punct, size_t begin, size_t end) {
    Token& token = out_.tokens.emplace_back();
    ++token_count_;
    token.kind = kind;
    token.punct = punct;
    token.begin = U32(begin);
    token.end = U32(end);
    token.trivia_begin = trivia_used_;
    token.trivia_end = U32(out_.trivia.size());
    trivia_used_ = token.trivia_end;
    token.at_line_start = at_line_start_;
    token.leading_space = leading_space_;
    token.text = text_.substr(begin, end - begin);
    at_line_start_ = false;
    leading_space_ = false;
  }

  const SourceFile& file_;
  std::string_view text_;
  bool plain_;  // no backslash in the file
  LexedFile out_;
  uint32_t trivia_used_ = 0;
  size_t token_count_ = 0;  // out_.tokens.size(), without a division per token
  bool at_line_start_ = true;
  bool leading_space_ = false;
};

}  // namespace

LexedFile Lex(const SourceFile& file) { return Lexer(file).Run(); }

std::string Reconstruct(const SourceFile& file, const LexedFile& lexed) {
  const std::string_view text = file.Text();
  std::string out;
  out.reserve(text.size());
  for (const Token& token : lexed.tokens) {
    for (uint32_t i = token.trivia_begin; i < token.trivia_end && i < lexed.trivia.size(); ++i) {
      const Trivia& t = lexed.trivia[i];
      out.append(text.substr(t.begin, t.end - t.begin));
    }
    out.append(token.text);
  }
  return out;
}

}  // namespace shaderport::glsl
