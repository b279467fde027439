#include "glsl/lex/lex_chars.h"

#include <cstdint>
#include <cstdio>

namespace shaderport::glsl {

size_t LineCommentEnd(std::string_view text, size_t p) {
  while (p < text.size()) {
    if (size_t len = ContinuationLength(text, p)) {
      p += len;  // as in C and glslang, an escaped newline continues the comment
    } else if (NewlineLength(text, p)) {
      return p;
    } else {
      ++p;
    }
  }
  return p;
}

size_t BlockCommentEnd(std::string_view text, size_t p) {
  p = SkipContinuations(text, p + 1);  // past '/'
  p = SkipContinuations(text, p + 1);  // past '*'
  while (p < text.size()) {
    if (text[p] == '*') {
      const size_t next = SkipContinuations(text, p + 1);
      if (next < text.size() && text[next] == '/') return next + 1;
      p = next;
    } else {
      ++p;
    }
  }
  return kNoEnd;
}

namespace {

// Length of the well-formed UTF-8 sequence at `p`, or 0.
size_t Utf8Length(std::string_view text, size_t p, uint32_t* code_point) {
  const auto lead = static_cast<unsigned char>(text[p]);
  size_t length = 0;
  uint32_t cp = 0;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2, cp = lead & 0x1F;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3, cp = lead & 0x0F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4, cp = lead & 0x07;
  } else {
    return 0;
  }
  if (p + length > text.size()) return 0;
  for (size_t i = 1; i < length; ++i) {
    const auto b = static_cast<unsigned char>(text[p + i]);
    if ((b & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (b & 0x3F);
  }
  if ((length == 3 && cp < 0x800) || (length == 4 && (cp < 0x10000 || cp > 0x10FFFF))) return 0;
  *code_point = cp;
  return length;
}

}  // namespace

size_t InvalidLength(std::string_view text, size_t p) {
  uint32_t cp = 0;
  const size_t length = Utf8Length(text, p, &cp);
  return length ? length : 1;
}

std::string DescribeInvalid(std::string_view bytes) {
  char buffer[96];
  const auto c = static_cast<unsigned char>(bytes[0]);
  uint32_t cp = 0;
  if (bytes.size() > 1 && Utf8Length(bytes, 0, &cp) == bytes.size()) {
    std::snprintf(buffer, sizeof buffer,
                  "non-ASCII character U+%04X: GLSL source outside comments is ASCII", cp);
  } else if (c == '\\') {
    std::snprintf(buffer, sizeof buffer, "stray '\\' that does not end a line");
  } else if (c >= 0x21 && c < 0x7F) {
    std::snprintf(buffer, sizeof buffer, "invalid character '%c' in GLSL source", c);
  } else {
    std::snprintf(buffer, sizeof buffer, "invalid byte 0x%02X in GLSL source", c);
  }
  return buffer;
}

}  // namespace shaderport::glsl
