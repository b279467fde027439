#include "base/printable.h"

namespace shaderport {
namespace {

constexpr char kHex[] = "0123456789abcdef";

std::string Escape(std::string_view text, bool line_breaks_as_spaces) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte == 0xC2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
        static_cast<unsigned char>(text[i + 1]) <= 0x9F) {
      const auto c1 = static_cast<unsigned char>(text[++i]);
      out += "\\u00";
      out += kHex[c1 >> 4];
      out += kHex[c1 & 15];
    } else if ((byte == '\n' || byte == '\r') && line_breaks_as_spaces) {
      out += ' ';
    } else if (byte == '\n') {
      out += "\\n";
    } else if (byte == '\r') {
      out += "\\r";
    } else if (byte == '\t') {
      out += "\\t";
    } else if (byte < 0x20 || byte == 0x7F) {
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 15];
    } else {
      out += static_cast<char>(byte);
    }
  }
  return out;
}

}  // namespace

std::string EscapeControlCharacters(std::string_view text) { return Escape(text, false); }

std::string OneLinePrintable(std::string_view text) { return Escape(text, true); }

}  // namespace shaderport
