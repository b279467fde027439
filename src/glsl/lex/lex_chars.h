// Character-level helpers of the lexer (not public API). "Logical" characters
// skip line continuations (backslash-newline), which GLSL ES 3.00 removes
// before tokenizing; the bytes stay in the token text so nothing is lost.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace shaderport::glsl {

inline constexpr size_t kNoEnd = static_cast<size_t>(-1);

// Character classes by table: the lexer asks for nearly every byte of a file, and a
// lookup is cheaper than the chains of comparisons.
inline constexpr uint8_t kSpaceClass = 1;       // horizontal space
inline constexpr uint8_t kIdentifierClass = 2;  // letter, digit or '_'
inline constexpr std::array<uint8_t, 256> kCharClass = [] {
  std::array<uint8_t, 256> table{};
  for (const char c : {' ', '\t', '\f', '\v'}) table[static_cast<unsigned char>(c)] = kSpaceClass;
  for (int c = 0; c < 256; ++c) {
    if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || (c >= '0' && c <= '9')) {
      table[static_cast<size_t>(c)] = kIdentifierClass;
    }
  }
  return table;
}();

inline bool IsHorizontalSpace(char c) {
  return kCharClass[static_cast<unsigned char>(c)] == kSpaceClass;
}
inline bool IsDigit(char c) { return c >= '0' && c <= '9'; }
inline bool IsHexDigit(char c) {
  return IsDigit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}
inline bool IsIdentifierStart(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
inline bool IsIdentifierChar(char c) {
  return kCharClass[static_cast<unsigned char>(c)] == kIdentifierClass;
}

// The four below run for nearly every byte of a file: inline.

// Length of the newline ("\n", "\r\n" or "\r") at `p`, or 0.
inline size_t NewlineLength(std::string_view text, size_t p) {
  if (p >= text.size()) return 0;
  if (text[p] == '\n') return 1;
  if (text[p] != '\r') return 0;
  return p + 1 < text.size() && text[p + 1] == '\n' ? 2 : 1;
}

// Length of the backslash-newline at `p`, or 0.
inline size_t ContinuationLength(std::string_view text, size_t p) {
  if (p >= text.size() || text[p] != '\\') return 0;
  const size_t nl = NewlineLength(text, p + 1);
  return nl ? nl + 1 : 0;
}

// `p` moved past any line continuations.
inline size_t SkipContinuations(std::string_view text, size_t p) {
  while (size_t len = ContinuationLength(text, p)) p += len;
  return p;
}

// The logical character `k` steps after the one at `p`; '\0' past the end.
inline char PeekLogical(std::string_view text, size_t p, int k) {
  for (int i = 0; i < k && p < text.size(); ++i) p = SkipContinuations(text, p + 1);
  return p < text.size() ? text[p] : '\0';
}
// End of the "//" comment at `p`: the next newline not escaped by a backslash.
size_t LineCommentEnd(std::string_view text, size_t p);
// One past the "*/" closing the comment at `p`, or kNoEnd when unterminated.
size_t BlockCommentEnd(std::string_view text, size_t p);
// Byte length of the invalid character at `p`: a whole UTF-8 sequence or one byte.
size_t InvalidLength(std::string_view text, size_t p);
// A message for an invalid character: "invalid character '$'", "... U+00A0 ...", ...
std::string DescribeInvalid(std::string_view bytes);

// Walks logical characters of one token. End() is one past the last consumed
// byte, so continuations after the token stay outside it.
class Cursor {
 public:
  Cursor(std::string_view text, size_t p) : text_(text), pos_(p), end_(p) {}
  char Ch() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
  char Peek(int k) const { return PeekLogical(text_, pos_, k); }
  void Bump() {
    if (pos_ >= text_.size()) return;
    end_ = pos_ + 1;
    pos_ = SkipContinuations(text_, pos_ + 1);
  }
  void SetEnd(size_t end) { pos_ = end_ = end; }
  size_t End() const { return end_; }

 private:
  std::string_view text_;
  size_t pos_;
  size_t end_;
};

}  // namespace shaderport::glsl
